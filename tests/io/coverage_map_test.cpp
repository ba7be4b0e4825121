#include "io/coverage_map.h"

#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <random>
#include <regex>

#include "io/coverage_map_crossings.h"
#include "io_test_util.h"

namespace covmap::io {
namespace {

using Json = nlohmann::json;
using testing::input_error_from;

// ---- building GeoJSON ----

// A ring of positions; closed (last = first) unless told otherwise.
Json ring(const std::vector<Point>& points, bool close = true) {
  Json out = Json::array();
  for (const Point& p : points) out.push_back({p.x, p.y});
  if (close) out.push_back({points.front().x, points.front().y});
  return out;
}

Json polygon(std::vector<Json> rings) { return {{"type", "Polygon"}, {"coordinates", rings}}; }

Json multipolygon(std::vector<std::vector<Json>> polygons) {
  Json coordinates = Json::array();
  for (auto& rings : polygons) coordinates.push_back(rings);
  return {{"type", "MultiPolygon"}, {"coordinates", coordinates}};
}

Json feature(Json sensor, Json geometry) {
  return {{"type", "Feature"}, {"properties", {{"sensor", sensor}}}, {"geometry", geometry}};
}

Json collection(std::vector<Json> features) { return {{"type", "FeatureCollection"}, {"features", features}}; }

std::vector<Point> square(double x, double y, double side) { return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}; }

CoverageMap parse(const Json& map, const CoverageMapOptions& options = {}) {
  return parse_coverage_map(map.dump(), "map.geojson", options);
}

InputError text_error(const std::string& text, const CoverageMapOptions& options = {}) {
  return input_error_from([&] { parse_coverage_map(text, "map.geojson", options); });
}
InputError error_of(const Json& map, const CoverageMapOptions& options = {}) { return text_error(map.dump(), options); }

CoverageMapOptions planar() {
  CoverageMapOptions options;
  options.planar = true;
  return options;
}

// A valid first feature, so the faulty one in each error test is features[1].
Json good() { return feature("a", polygon({ring(square(0, 0, 1))})); }

// ---- oracles ----

double shoelace_area(const Ring& r) {
  double twice = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[i], b = r[(i + 1) % r.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return twice / 2;
}

// got is expected as a cycle, starting anywhere, in either direction.
bool same_cycle(const Ring& got, const std::vector<Point>& expected) {
  const std::size_t n = expected.size();
  if (got.size() != n) return false;
  for (const int direction : {1, -1}) {
    for (std::size_t start = 0; start < n; ++start) {
      bool all = true;
      for (std::size_t i = 0; i < n && all; ++i) {
        const Point e = expected[(start + n + direction * static_cast<std::ptrdiff_t>(i) % static_cast<std::ptrdiff_t>(n)) % n];
        all = got[i].x == e.x && got[i].y == e.y;
      }
      if (all) return true;
    }
  }
  return false;
}

double geodesic_m(double lon1, double lat1, double lon2, double lat2) {
  double s = 0;
  GeographicLib::Geodesic::WGS84().Inverse(lat1, lon1, lat2, lon2, s);
  return s;
}

// ---- valid maps ----

TEST(CoverageMap, PlanarPolygonWithHoleIsNormalized) {
  // Outer ring clockwise with a repeated vertex; hole counter-clockwise: both the wrong way round.
  const std::vector<Point> outer = {{0, 0}, {0, 10}, {10, 10}, {10, 0}, {10, 0}};
  const std::vector<Point> hole = {{2, 2}, {4, 2}, {4, 4}, {2, 4}};
  const auto map = parse(collection({feature("a", polygon({ring(outer), ring(hole)}))}), planar());
  ASSERT_EQ(map.cells.size(), 1u);
  EXPECT_FALSE((map.frame != nullptr));
  EXPECT_EQ(map.max_scale_distortion, 0.0);
  EXPECT_EQ(map.vertex_count, 8u);
  const MapCell& cell = map.cells[0];
  EXPECT_EQ(cell.sensor, "a");
  EXPECT_EQ(cell.feature, 0);
  ASSERT_EQ(cell.polygons.size(), 1u);
  const MapPolygon& p = cell.polygons[0];
  EXPECT_DOUBLE_EQ(shoelace_area(p.outer), 100.0);
  EXPECT_TRUE(same_cycle(p.outer, {{0, 0}, {0, 10}, {10, 10}, {10, 0}}));
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(shoelace_area(p.holes[0]), -4.0);
  EXPECT_TRUE(same_cycle(p.holes[0], hole));
}

TEST(CoverageMap, MultiPolygonAndIntegerSensorAndRightOrientationKept) {
  const auto map = parse(collection({good(), feature(17, multipolygon({{ring(square(2, 0, 1))}, {ring(square(4, 0, 2))}}))}),
                         planar());
  ASSERT_EQ(map.cells.size(), 2u);
  EXPECT_EQ(map.cells[1].sensor, "17");
  EXPECT_EQ(map.cells[1].feature, 1);
  ASSERT_EQ(map.cells[1].polygons.size(), 2u);
  EXPECT_DOUBLE_EQ(shoelace_area(map.cells[1].polygons[0].outer), 1.0);
  EXPECT_DOUBLE_EQ(shoelace_area(map.cells[1].polygons[1].outer), 4.0);
  EXPECT_TRUE(same_cycle(map.cells[1].polygons[1].outer, square(4, 0, 2)));
  EXPECT_EQ(map.vertex_count, 12u);
}

TEST(CoverageMap, OtherSensorPropertyAndAltitudeIgnored) {
  Json f = {{"type", "Feature"},
            {"properties", {{"cell_id", "north"}, {"sensor", 3}}},
            {"geometry", {{"type", "Polygon"}, {"coordinates", {{{0, 0, 500}, {1, 0, 510}, {1, 1, 520}, {0, 0, 500}}}}}}};
  CoverageMapOptions options = planar();
  options.sensor_property = "cell_id";
  const auto map = parse(collection({f}), options);
  EXPECT_EQ(map.cells[0].sensor, "north");
  EXPECT_EQ(map.cells[0].polygons[0].outer.size(), 3u);
}

// A feature with properties {"sensor": sensor, "name": name} (no name member when name is absent).
Json named_feature(Json sensor, std::optional<Json> name, double x) {
  Json f = feature(std::move(sensor), polygon({ring(square(x, 0, 1))}));
  if (name) f["properties"]["name"] = *name;
  return f;
}

TEST(CoverageMapNames, KeptPerCellAbsentOrNullIsEmptyAndDisagreementIsNoError) {
  // Sensor "a" has two cells naming it differently: both are read as written (the audit takes the
  // first); "b" has no name, "c" a null one.
  const auto map = parse(collection({named_feature("a", "Bern", 0), named_feature("b", std::nullopt, 2),
                                     named_feature("a", "Berne", 4), named_feature("c", nullptr, 6)}),
                         planar());
  ASSERT_EQ(map.cells.size(), 4u);
  EXPECT_EQ(map.cells[0].name, "Bern");
  EXPECT_EQ(map.cells[1].name, "");
  EXPECT_EQ(map.cells[2].name, "Berne");
  EXPECT_EQ(map.cells[3].name, "");
  EXPECT_EQ(map.cells[2].sensor, "a");
}

TEST(CoverageMapNames, NamePropertyAsTheSensorPropertyIsTheId) {
  // With --sensor-property name the name is the id (an integer kept as its decimal text too), and
  // the default "sensor" property is then only another property.
  Json f = feature("ignored", polygon({ring(square(0, 0, 1))}));
  f["properties"]["name"] = 42;
  CoverageMapOptions options = planar();
  options.sensor_property = "name";
  const auto map = parse(collection({f, named_feature("x", "Thun", 2)}), options);
  EXPECT_EQ(map.cells[0].sensor, "42");
  EXPECT_EQ(map.cells[0].name, "42");
  EXPECT_EQ(map.cells[1].sensor, "Thun");
  EXPECT_EQ(map.cells[1].name, "Thun");
}

TEST(CoverageMapNames, NonStringNameIsAnErrorNamingTheFeature) {
  const auto e = error_of(collection({named_feature("a", "ok", 0), named_feature("b", 7, 2)}), planar());
  EXPECT_EQ(e.item(), "features[1] (sensor 'b')");
  EXPECT_EQ(e.message(), "property \"name\" must be a string (got number 7)");
}

TEST(CoverageMap, PinchedRingIsAccepted) {
  // Touching itself at a vertex is not a crossing (see the contract in coverage_map.h).
  const std::vector<Point> figure_eight = {{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 1}};
  const auto map = parse(collection({feature("a", polygon({ring(figure_eight)}))}), planar());
  EXPECT_EQ(map.cells[0].polygons[0].outer.size(), 6u);
}

TEST(CoverageMap, GeographicMapIsProjectedAboutItsBoundingBoxCentre) {
  // Two cells side by side covering lon 7.5..8.5, lat 46.6..47.6.
  const auto map = parse(collection({feature("west", polygon({ring({{7.5, 46.6}, {8.0, 46.6}, {8.0, 47.6}, {7.5, 47.6}})})),
                                     feature("east", polygon({ring({{8.0, 46.6}, {8.5, 46.6}, {8.5, 47.6}, {8.0, 47.6}})}))}));
  ASSERT_TRUE((map.frame != nullptr));
  EXPECT_DOUBLE_EQ(map.frame->reference().lon, 8.0);
  EXPECT_DOUBLE_EQ(map.frame->reference().lat, 47.1);

  // Worst distortion at the map's lowest latitude and widest longitude offset; the spherical closed
  // form k = 1 / sqrt(1 - (cos(lat) sin(dlon))^2) agrees with the ellipsoid to ~0.5% of k - 1.
  const double b = std::cos(46.6 * std::numbers::pi / 180) * std::sin(0.5 * std::numbers::pi / 180);
  const double expected = 1 / std::sqrt(1 - b * b) - 1;
  EXPECT_NEAR(map.max_scale_distortion, expected, 0.01 * expected);

  // Planar lengths are geodesic lengths times a factor in [1, 1 + distortion].
  const Ring& west = map.cells[0].polygons[0].outer;
  EXPECT_GT(shoelace_area(west), 0);
  // The south-west corner (7.5, 46.6) as read back, against an independent geodesic length.
  const Point sw = *std::min_element(west.begin(), west.end(), [](Point a, Point b) { return a.x + a.y < b.x + b.y; });
  const Point se = map.frame->forward(8.0, 46.6);
  const double planar_m = std::hypot(sw.x - se.x, sw.y - se.y);
  const double true_m = geodesic_m(7.5, 46.6, 8.0, 46.6);
  EXPECT_GE(planar_m / true_m, 1 - 1e-9);
  EXPECT_LE(planar_m / true_m, 1 + map.max_scale_distortion + 1e-9);
}

TEST(CoverageMap, MapAcrossTheAntimeridianIsCentredOnIt) {
  const auto map = parse(collection({feature("w", polygon({ring({{179.8, 10}, {179.9, 10}, {179.9, 10.1}, {179.8, 10.1}})})),
                                     feature("e", polygon({ring({{-179.9, 10}, {-179.8, 10}, {-179.8, 10.1}, {-179.9, 10.1}})}))}));
  ASSERT_TRUE((map.frame != nullptr));
  EXPECT_NEAR(std::abs(map.frame->reference().lon), 180.0, 1e-9);
  EXPECT_LT(map.max_scale_distortion, 1e-5);
  // The two cells are 0.2 degrees apart across the antimeridian, not 359.8 degrees.
  const Point a = map.frame->forward(179.9, 10), b = map.frame->forward(-179.9, 10);
  const double ratio = std::hypot(a.x - b.x, a.y - b.y) / geodesic_m(179.9, 10, -179.9, 10);
  EXPECT_GE(ratio, 1 - 1e-9);
  EXPECT_LE(ratio, 1 + map.max_scale_distortion + 1e-9);
}

TEST(CoverageMap, ReadsFromFile) {
  testing::TempDir dir;
  const auto file = dir.write("map.geojson", collection({good()}).dump());
  EXPECT_EQ(read_coverage_map(file, planar()).cells.size(), 1u);
  EXPECT_NE(input_error_from([&] { read_coverage_map(dir / "absent.geojson"); }).message().find("cannot open"), std::string::npos);
}

// ---- errors: each names the file and the feature ----

TEST(CoverageMapErrors, InvalidJsonGivesLineAndByte) {
  const auto e = text_error("{\"type\": \"FeatureCollection\",\n \"features\": [}");
  EXPECT_EQ(e.file, "map.geojson");
  EXPECT_EQ(e.line(), 2);
  EXPECT_NE(e.message().find("invalid JSON at byte"), std::string::npos) << e.what();
}

TEST(CoverageMapErrors, OverflowingNumberIsTheOnlyNonFiniteAndIsCaught) {
  const auto e = text_error("{\"type\":\"FeatureCollection\",\"features\":[\n{\"type\":\"Feature\",\"geometry\":{\"type\":\"Polygon\","
                          "\"coordinates\":[[[0,0],[1e999,0],[1,1],[0,0]]]}}]}");
  EXPECT_EQ(e.line(), 2);
  EXPECT_NE(e.message().find("1e999"), std::string::npos) << e.what();
}

TEST(CoverageMapErrors, NotAFeatureCollection) {
  const auto e = error_of(good());
  EXPECT_EQ(e.message(), "expected a GeoJSON FeatureCollection with one Feature per coverage cell (got type string \"Feature\")");
  EXPECT_NE(error_of(Json::array()).message().find("got an array"), std::string::npos);
}

TEST(CoverageMapErrors, NoFeatures) {
  const auto e = error_of(collection({}));
  EXPECT_EQ(e.item(), "features");
  EXPECT_EQ(e.message(), "the map has no features");
}

TEST(CoverageMapErrors, NotAFeature) {
  const auto e = error_of(collection({good(), polygon({ring(square(0, 0, 1))})}), planar());
  EXPECT_EQ(e.item(), "features[1]");
  EXPECT_EQ(e.message(), "must be a GeoJSON Feature (got type string \"Polygon\")");
}

TEST(CoverageMapErrors, MissingSensorPropertyListsTheOthers) {
  Json f = good();
  f["properties"] = {{"name", "x"}, {"power", 3}};
  const auto e = error_of(collection({good(), f}), planar());
  EXPECT_EQ(e.item(), "features[1]");
  EXPECT_EQ(e.message(), "missing property \"sensor\" (properties present: \"name\", \"power\"); choose one with --sensor-property");
  f.erase("properties");
  EXPECT_EQ(error_of(collection({good(), f}), planar()).message(), "missing property \"sensor\" (the feature has no properties)");
}

TEST(CoverageMapErrors, SensorPropertyOfTheWrongType) {
  for (const auto& [value, message] : std::vector<std::pair<Json, std::string>>{
           {1.5, "property \"sensor\" must be a string or an integer (got number 1.5)"},
           {true, "property \"sensor\" must be a string or an integer (got true)"},
           {"", "property \"sensor\" must not be empty"}}) {
    const auto e = error_of(collection({good(), feature(value, polygon({ring(square(0, 0, 1))}))}), planar());
    EXPECT_EQ(e.item(), "features[1]");
    EXPECT_EQ(e.message(), message);
  }
}

TEST(CoverageMapErrors, UnsupportedGeometry) {
  const auto e = error_of(collection({good(), feature("b", {{"type", "LineString"}, {"coordinates", {{0, 0}, {1, 1}}}})}), planar());
  EXPECT_EQ(e.item(), "features[1] (sensor 'b')");
  EXPECT_EQ(e.message(), "geometry type \"LineString\" is not supported; a coverage map needs Polygon or MultiPolygon");
  EXPECT_EQ(error_of(collection({good(), feature("b", nullptr)}), planar()).message(),
            "geometry is null; each coverage cell needs a Polygon or MultiPolygon");
}

TEST(CoverageMapErrors, UnclosedRing) {
  const auto e = error_of(collection({good(), feature("b", polygon({ring({{0, 0}, {1, 0}, {1, 1}}, false)}))}), planar());
  EXPECT_EQ(e.item(), "features[1] (sensor 'b')");
  EXPECT_EQ(e.message(), "outer ring is not closed: its last position 2 (1, 1) differs from position 0 (0, 0); RFC 7946 "
                         "requires a ring to end where it starts");
}

TEST(CoverageMapErrors, TooFewDistinctVertices) {
  const auto e = error_of(collection({good(), feature("b", multipolygon({{ring(square(5, 5, 1))},
                                                                         {ring(square(0, 0, 1)), ring({{0.2, 0.2}, {0.5, 0.5}, {0.5, 0.5}})}}))}),
                          planar());
  EXPECT_EQ(e.item(), "features[1] (sensor 'b')");
  EXPECT_EQ(e.message(), "hole 1 of polygon 1 has 2 distinct vertices; a ring needs at least 3");
}

TEST(CoverageMapErrors, ZeroAreaAndDoublingBack) {
  EXPECT_EQ(error_of(collection({good(), feature("b", polygon({ring({{0, 0}, {1, 1}, {3, 3}})}))}), planar()).message(),
            "outer ring has zero area (all 3 distinct vertices lie on one line)");
  // (0,0) is the lowest vertex and its neighbours (4,4) and (2,2) lie on one ray from it.
  EXPECT_EQ(error_of(collection({good(), feature("b", polygon({ring({{0, 0}, {2, 2}, {-1, 3}, {4, 4}})}))}), planar()).message(),
            "outer ring doubles back on itself at position 0 (0, 0) (the edges before and after it overlap)");
}

TEST(CoverageMapErrors, PlanarLookingCoordinatesWithoutPlanarFlag) {
  const Json map = collection({feature("a", polygon({ring(square(512345.5, 5223001.25, 100))})),
                               feature("b", polygon({ring(square(512445.5, 5223001.25, 100))}))});
  const auto e = error_of(map);
  ASSERT_EQ(e.problems.size(), 2u);  // one per feature, not one per vertex
  EXPECT_EQ(e.item(), "features[0] (sensor 'a')");
  EXPECT_EQ(e.message(), "outer ring, position 0: not a longitude/latitude; coordinates look planar (x=512345.5, "
                         "y=5223001.25); use --planar");
  EXPECT_EQ(parse(map, planar()).cells.size(), 2u);
}

TEST(CoverageMapErrors, SelfCrossingRing) {
  const auto e = error_of(collection({good(), feature("b", polygon({ring({{0, 0}, {10, 10}, {10, 0}, {0, 10}})}))}), planar());
  EXPECT_EQ(e.item(), "features[1] (sensor 'b')");
  EXPECT_EQ(e.message(), "outer ring crosses itself: the edge from position 0 (0, 0) to position 1 (10, 10) crosses the edge "
                         "from position 2 (10, 0) to position 3 (0, 10)");
}

TEST(CoverageMapErrors, HoleCrossingTheOuterRing) {
  const auto e = error_of(collection({good(), feature("b", polygon({ring(square(0, 0, 10)), ring({{8, 8}, {12, 8}, {12, 9}})}))}),
                          planar());
  EXPECT_EQ(e.item(), "features[1] (sensor 'b')");
  EXPECT_EQ(e.message().rfind("hole 1 crosses the outer ring: the edge from position 1 (10, 0) to position 2 (10, 10) of the "
                              "outer ring crosses the edge from position 0 (8, 8) to position 1 (12, 8) of hole 1", 0),
            0u)
      << e.what();
}

TEST(CoverageMapErrors, ForeignCrsNeedsPlanar) {
  Json map = collection({good()});
  map["crs"] = {{"type", "name"}, {"properties", {{"name", "urn:ogc:def:crs:EPSG::32632"}}}};
  const auto e = error_of(map);
  EXPECT_EQ(e.item(), "crs");
  EXPECT_EQ(e.problems.size(), 1u);  // the geometry of misread numbers is not judged
  EXPECT_NE(e.message().find("\"urn:ogc:def:crs:EPSG::32632\""), std::string::npos);
  EXPECT_NE(e.message().find("--planar"), std::string::npos);
  EXPECT_EQ(parse(map, planar()).cells.size(), 1u);
}

// A CRS-aware caller (gis/, through PROJ) resolves the declaration; the positions are
// then that CRS's metres, used as they are, and the map carries the CRS's frame.
TEST(CoverageMapCrs, DeclaredCrsIsResolvedIntoTheMapsFrame) {
  Json map = collection({good()});
  map["crs"] = {{"type", "name"}, {"properties", {{"name", "urn:ogc:def:crs:EPSG::2056"}}}};
  CoverageMapOptions o;
  std::string asked;
  o.resolve_crs = [&](const std::string& name) {
    asked = name;
    return std::make_shared<testing::ProjectedForTest>(LocalProjection::about(7.0, 46.0));
  };
  const CoverageMap m = parse(map, o);
  EXPECT_EQ(asked, "urn:ogc:def:crs:EPSG::2056");
  ASSERT_TRUE(m.frame);
  EXPECT_EQ(m.frame->kind(), FrameKind::kProjectedCrs);
  const CoverageMap planar_reading = parse(collection({good()}), planar());
  const auto& got = m.cells[0].polygons[0].outer;  // the positions as they are
  const auto& want = planar_reading.cells[0].polygons[0].outer;
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].x, want[i].x);
    EXPECT_EQ(got[i].y, want[i].y);
  }
  // --planar with a declaration the resolver accepts: the data say what they are.
  o.planar = true;
  const auto e = error_of(map, o);
  EXPECT_NE(e.message().find("drop --planar"), std::string::npos) << e.what();
  // --planar with a label no resolver knows: only a label, accepted.
  o.resolve_crs = [](const std::string&) -> std::shared_ptr<const MapFrame> { throw std::invalid_argument("unknown"); };
  EXPECT_EQ(parse(map, o).cells.size(), 1u);
}

TEST(CoverageMapCrs, RefusedCrsIsSaidOnceWithTheResolversReason) {
  Json map = collection({good(), good()});
  map["crs"] = {{"type", "name"}, {"properties", {{"name", "EPSG:2227"}}}};
  CoverageMapOptions o;
  o.resolve_crs = [](const std::string&) -> std::shared_ptr<const MapFrame> {
    throw std::invalid_argument("measures in US survey foot");
  };
  const auto e = error_of(map, o);
  ASSERT_EQ(e.problems.size(), 1u) << e.what();  // not again as positions out of lon/lat range
  EXPECT_EQ(e.item(), "crs");
  EXPECT_EQ(e.message(), "measures in US survey foot");
}

TEST(CoverageMapErrors, Wgs84CrsSpellingsAreAccepted) {
  for (const std::string name : {"urn:ogc:def:crs:OGC:1.3:CRS84", "EPSG:4326", "http://www.opengis.net/def/crs/EPSG/0/4326"}) {
    Json map = collection({good(), good()});
    map["crs"] = {{"type", "name"}, {"properties", {{"name", name}}}};
    map["features"][1]["crs"] = {{"type", "name"}, {"properties", {{"name", "urn:ogc:def:crs:OGC::CRS84"}}}};
    EXPECT_EQ(parse(map).cells.size(), 2u) << name;
  }
}

TEST(CoverageMapErrors, MixedCrsIsRefusedEvenWhenPlanar) {
  Json map = collection({good(), good()});
  map["features"][0]["crs"] = {{"type", "name"}, {"properties", {{"name", "EPSG:32632"}}}};
  map["features"][1]["crs"] = {{"type", "name"}, {"properties", {{"name", "EPSG:32633"}}}};
  const auto e = error_of(map, planar());
  EXPECT_EQ(e.item(), "features[1].crs");
  EXPECT_EQ(e.message(), "declares coordinate reference system \"EPSG:32633\" but features[0].crs declares \"EPSG:32632\"; one "
                         "file must use one coordinate reference system");
}

TEST(CoverageMapErrors, AllProblemsAreCollected) {
  const auto e = error_of(collection({good(), feature("b", polygon({ring({{0, 0}, {1, 0}}, false)})), good(),
                                      feature(2.5, polygon({ring(square(0, 0, 1))}))}),
                          planar());
  ASSERT_EQ(e.problems.size(), 2u) << e.what();
  EXPECT_EQ(e.problems[0].item, "features[1] (sensor 'b')");
  EXPECT_EQ(e.problems[1].item, "features[3]");
  EXPECT_NE(std::string(e.what()).find("map.geojson: 2 problems"), std::string::npos);
}

// ---- large rings ----

// A wavy ring of n vertices around the origin (star-shaped, so simple).
std::vector<Point> wavy_ring(std::size_t n) {
  std::vector<Point> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const double r = 1000 + 50 * std::sin(57 * t);
    out.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return out;
}

TEST(CoverageMapLarge, HundredThousandVertexRingParsesAndCrossingIsFound) {
  constexpr std::size_t n = 100000;
  auto points = wavy_ring(n);
  const auto map = parse(collection({feature("big", polygon({ring(points)}))}), planar());
  EXPECT_EQ(map.vertex_count, n);
  EXPECT_GT(shoelace_area(map.cells[0].polygons[0].outer), 0);

  std::swap(points[10], points[10 + n / 2]);  // two spikes across the ring: they cross
  const auto e = error_of(collection({feature("big", polygon({ring(points)}))}), planar());
  // The edges at positions 9-10-11 cross those at 50009-50010-50011; the message names one pair.
  const std::regex named("^outer ring crosses itself: the edge from position (9|10) .* crosses the edge from position (50009|50010) ");
  EXPECT_TRUE(std::regex_search(e.message(), named)) << e.what();
}

// ---- the crossing finder against brute force ----

// Exact orientation for small integer coordinates.
int orient(Point a, Point b, Point c) {
  const auto v = static_cast<std::int64_t>((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  return (v > 0) - (v < 0);
}

std::optional<detail::Crossing> brute_force_crossing(const std::vector<std::vector<Point>>& rings) {
  std::vector<detail::EdgeRef> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (std::size_t i = 0; i < rings[r].size(); ++i) edges.push_back({r, i});
  }
  const auto end = [&](detail::EdgeRef e, std::size_t k) { return rings[e.ring][(e.edge + k) % rings[e.ring].size()]; };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Point p1 = end(edges[i], 0), p2 = end(edges[i], 1), q1 = end(edges[j], 0), q2 = end(edges[j], 1);
      if (orient(p1, p2, q1) * orient(p1, p2, q2) < 0 && orient(q1, q2, p1) * orient(q1, q2, p2) < 0) {
        return detail::Crossing{edges[i], edges[j]};
      }
    }
  }
  return std::nullopt;
}

TEST(CoverageMapCrossings, AgreesWithBruteForceOnDegenerateIntegerRings) {
  // Small integer grids make touching, collinear and overlapping edges common, which must not
  // count; an offset like UTM northings checks the grid's rounding slack.
  std::mt19937 random(11);
  int crossings = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const double offset = trial % 2 ? 5.0e6 : 0.0;
    std::uniform_int_distribution<int> coordinate(0, trial % 3 ? 12 : 400), size(3, 40), count(1, 3);
    const bool star = trial % 4 == 0;
    std::vector<std::vector<Point>> rings(star ? 1 : static_cast<std::size_t>(count(random)));
    for (auto& r : rings) {
      const int n = size(random);
      while (static_cast<int>(r.size()) < n) {
        const Point p{offset + coordinate(random), offset + coordinate(random)};
        if (!r.empty() && r.back().x == p.x && r.back().y == p.y) continue;
        r.push_back(p);
      }
      if (star) {
        // Sorted by angle about an inner point: star-shaped, so simple unless degenerate.
        const Point c{offset + 0.5 + coordinate(random) / 2, offset + 0.5 + coordinate(random) / 2};
        std::sort(r.begin(), r.end(), [&](Point p, Point q) {
          return std::atan2(p.y - c.y, p.x - c.x) < std::atan2(q.y - c.y, q.x - c.x);
        });
      }
      if (trial % 5 == 1) r.push_back({offset + 5000, offset});  // one long edge among short ones
    }
    const auto want = brute_force_crossing(rings);
    const auto got = detail::find_crossing(rings);
    ASSERT_EQ(got.has_value(), want.has_value()) << "trial " << trial;
    if (!want) continue;
    ++crossings;
    // One crossing is named (the first the sweep meets, not necessarily the smallest pair): it must
    // be a real one.
    ASSERT_LT(got->first, got->second) << "trial " << trial;
    const auto end = [&](detail::EdgeRef e, std::size_t k) { return rings[e.ring][(e.edge + k) % rings[e.ring].size()]; };
    const Point p1 = end(got->first, 0), p2 = end(got->first, 1), q1 = end(got->second, 0), q2 = end(got->second, 1);
    EXPECT_TRUE(orient(p1, p2, q1) * orient(p1, p2, q2) < 0 && orient(q1, q2, p1) * orient(q1, q2, p2) < 0)
        << "trial " << trial;
  }
  EXPECT_GT(crossings, 100);  // both answers are well represented
  EXPECT_GT(600 - crossings, 60);
}

}  // namespace
}  // namespace covmap::io
