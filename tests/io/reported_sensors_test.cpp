#include "io/reported_sensors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <stdexcept>

#include "io/local_projection.h"
#include "io_test_util.h"

namespace covmap::io {
namespace {

using testing::input_error_from;
using testing::ProjectedForTest;

const LocalProjection& swiss() {
  static const LocalProjection p = LocalProjection::about(8.0, 47.0);
  return p;
}

ReportedSensorOptions planar_map() { return {}; }

ReportedSensorOptions geographic_map(std::optional<double> alpha = std::nullopt) {
  ReportedSensorOptions options;
  options.frame = &swiss();
  options.alpha = alpha;
  return options;
}

std::vector<ReportedSensor> csv(const std::string& text, const ReportedSensorOptions& options) {
  return parse_reported_sensors(text, "sensors.csv", options);
}
InputError csv_error(const std::string& text, const ReportedSensorOptions& options) {
  return input_error_from([&] { csv(text, options); });
}

// ---- power and weight ----

TEST(PowerWeight, ClosedForm) {
  EXPECT_DOUBLE_EQ(weight_from_power(30, 3), 10.0);      // 10^(30 / 30)
  EXPECT_DOUBLE_EQ(weight_from_power(0, 3.5), 1.0);
  EXPECT_DOUBLE_EQ(weight_from_power(-20, 2), 0.1);      // 10^(-20 / 20)
  EXPECT_DOUBLE_EQ(power_from_weight(100, 2), 40.0);     // 10 * 2 * log10(100)
  std::mt19937 random(3);
  std::uniform_real_distribution<double> power(-30, 60), alpha(1.5, 6);
  for (int i = 0; i < 100; ++i) {
    const double p = power(random), a = alpha(random);
    EXPECT_NEAR(power_from_weight(weight_from_power(p, a), a), p, 1e-12);
  }
}

TEST(PowerWeight, StrongestReceivedPowerIsTheWeightedVoronoiOwner) {
  // The reason for the formula: under log-distance path loss P_rx = P - 10 alpha log10(d), the
  // sensor received loudest at a point is the one minimizing d / weight_from_power(P, alpha).
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-1000, 1000), power(0, 40);
  const double alpha = 3.5;
  std::vector<std::array<double, 3>> sensors(8);
  for (auto& s : sensors) s = {coordinate(random), coordinate(random), power(random)};
  for (int trial = 0; trial < 500; ++trial) {
    const double x = coordinate(random), y = coordinate(random);
    std::size_t loudest = 0, nearest = 0;
    double best_rx = -INFINITY, best_distance = INFINITY;
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      const double d = std::hypot(x - sensors[i][0], y - sensors[i][1]);
      const double rx = sensors[i][2] - 10 * alpha * std::log10(d);
      if (rx > best_rx) best_rx = rx, loudest = i;
      if (d / weight_from_power(sensors[i][2], alpha) < best_distance) best_distance = d / weight_from_power(sensors[i][2], alpha), nearest = i;
    }
    EXPECT_EQ(loudest, nearest);
  }
}

TEST(PowerWeight, RejectsBadAlphaAndWeight) {
  EXPECT_THROW(weight_from_power(10, 0), std::invalid_argument);
  EXPECT_THROW(weight_from_power(10, NAN), std::invalid_argument);
  EXPECT_THROW(power_from_weight(0, 3), std::invalid_argument);
  ReportedSensorOptions options;
  options.alpha = -1;
  EXPECT_THROW(csv("id,x,y,weight\na,0,0,1\n", options), std::invalid_argument);
}

// ---- CSV ----

TEST(ReportedSensorsCsv, PlanarWithWeightsAndOptionalSigmas) {
  const auto s = csv("# reported\nID,note,x,y,weight,position_sigma_m,power_sigma_db\n"
                     "a,roof,0,0,1,5,\n"
                     "\"b, west\",,10.5,-3,2.5,,1.5\n",
                     planar_map());
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].id, "a");
  EXPECT_EQ(s[0].position.x, 0);
  EXPECT_EQ(s[0].weight, 1.0);
  EXPECT_EQ(s[0].position_sigma_m, 5.0);
  EXPECT_FALSE(s[0].power_sigma_db.has_value());
  EXPECT_FALSE(s[0].lon.has_value());
  EXPECT_EQ(s[0].origin, "line 3");
  EXPECT_EQ(s[1].id, "b, west");
  EXPECT_EQ(s[1].position.x, 10.5);
  EXPECT_EQ(s[1].position.y, -3);
  EXPECT_EQ(s[1].weight, 2.5);
  EXPECT_FALSE(s[1].position_sigma_m.has_value());
  EXPECT_EQ(s[1].power_sigma_db, 1.5);
  EXPECT_FALSE(s[1].tx_power_dbm.has_value());
}

TEST(ReportedSensorsCsv, LonLatWithPowerIsProjectedAndWeighted) {
  const auto s = csv("id,lon,lat,tx_power_dbm\nn,8.01,47.02,35\ns,7.99,46.98,28\n", geographic_map(3.5));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].lon, 8.01);
  EXPECT_EQ(s[0].lat, 47.02);
  EXPECT_EQ(s[0].tx_power_dbm, 35.0);
  EXPECT_DOUBLE_EQ(*s[0].weight, std::pow(10.0, 35.0 / 35.0));
  EXPECT_DOUBLE_EQ(*s[1].weight, std::pow(10.0, 28.0 / 35.0));
  const auto expected = swiss().forward(8.01, 47.02);
  EXPECT_EQ(s[0].position.x, expected.x);
  EXPECT_EQ(s[0].position.y, expected.y);
  EXPECT_GT(s[0].position.x, 0);  // east and north of the centre (8, 47)
  EXPECT_GT(s[0].position.y, 0);
}

TEST(ReportedSensorsCsv, WeightAsReadWinsOverPower) {
  const auto s = csv("id,x,y,weight,tx_power_dbm\na,0,0,7,30\nb,1,0,,30\n", [] {
    ReportedSensorOptions o;
    o.alpha = 3;
    return o;
  }());
  EXPECT_EQ(s[0].weight, 7.0);
  EXPECT_EQ(s[0].tx_power_dbm, 30.0);
  EXPECT_DOUBLE_EQ(*s[1].weight, 10.0);
}

TEST(ReportedSensorsCsv, PowerWithoutAlphaIsOneProblem) {
  const auto e = csv_error("id,x,y,tx_power_dbm\na,0,0,30\nb,1,0,31\nc,2,0,32\n", planar_map());
  ASSERT_EQ(e.problems.size(), 1u);
  EXPECT_EQ(e.message(), "tx_power_dbm needs --alpha (the path-loss exponent) to become a weight (sensor 'a' (line 2) and 2 more sensors)");
  // With a weight beside the power, alpha is not needed.
  EXPECT_EQ(csv("id,x,y,weight,tx_power_dbm\na,0,0,1,30\n", planar_map()).size(), 1u);
}

TEST(ReportedSensorsCsv, PositionsMustMatchTheMap) {
  EXPECT_EQ(csv_error("id,lon,lat,weight\na,8,47,1\n", planar_map()).message(),
            "positions are lon/lat but the map is planar, so there is no projection to place them with; give x/y in the "
            "map's units (sensor 'a' (line 2))");
  EXPECT_EQ(csv_error("id,x,y,weight\na,8,47,1\nb,9,47,1\n", geographic_map()).message(),
            "positions are x/y but the map is in lon/lat; give lon/lat, name the CRS of the x/y with --sensor-crs (e.g. "
            "EPSG:2056), or use --planar if the map is planar too (sensor 'a' (line 2) and 1 more sensor)");
}

TEST(ReportedSensorsCsv, DuplicateIdsAndPositionsNameBoth) {
  const auto e = csv_error("id,x,y,weight\na,0,0,1\nb,1,1,1\na,2,2,1\nc,1,1,2\n", planar_map());
  ASSERT_EQ(e.problems.size(), 2u) << e.what();
  EXPECT_EQ(e.problems[0].line, 4);
  EXPECT_EQ(e.problems[0].item, "sensor 'a'");
  EXPECT_EQ(e.problems[0].message, "duplicate id; first used by sensor 'a' (line 2)");
  EXPECT_EQ(e.problems[1].line, 5);
  EXPECT_EQ(e.problems[1].message, "same position (1, 1) as sensor 'b' (line 3)");
}

TEST(ReportedSensorsCsv, ValueProblemsAreCollected) {
  const auto e = csv_error("id,lon,lat,weight,tx_power_dbm,position_sigma_m\n"
                           "a,8,47,0,,\n"
                           "b,512000,5200000,1,,\n"
                           "c,8.1,47,,,\n"
                           "d,8.2,47,1,,-2\n"
                           ",8.3,47,1,,\n"
                           "f,8.4,47,x,,\n",
                           geographic_map());
  ASSERT_EQ(e.problems.size(), 6u) << e.what();
  EXPECT_EQ(e.problems[0].message, "weight must be positive (got 0)");
  EXPECT_EQ(e.problems[1].message, "not a longitude/latitude; coordinates look planar (x=512000, y=5200000); use --planar with a planar map");
  EXPECT_EQ(e.problems[2].message, "needs a weight or a tx_power_dbm");
  EXPECT_EQ(e.problems[3].message, "position_sigma_m must be positive (got -2)");
  EXPECT_EQ(e.problems[4].item, "row");
  EXPECT_EQ(e.problems[4].message, "id is empty");
  EXPECT_EQ(e.problems[5].line, 7);
  EXPECT_EQ(e.problems[5].message, "weight is not a number (got 'x')");
}

TEST(ReportedSensorsCsv, HeaderProblems) {
  EXPECT_EQ(csv_error("id,x,weight\n", planar_map()).message(), "needs both x and y (for example: id,lon,lat,tx_power_dbm)");
  EXPECT_EQ(csv_error("name,lon,lat\n", planar_map()).message(),
            "needs an id column, a weight or tx_power_dbm column (for example: id,lon,lat,tx_power_dbm)");
  EXPECT_EQ(csv_error("id,x,y,lon,weight\n", planar_map()).message(), "needs both lon and lat (for example: id,lon,lat,tx_power_dbm)");
  EXPECT_EQ(csv_error("id,x,y,weight,Weight\n", planar_map()).message(), "repeated column 'weight'");
  EXPECT_EQ(csv_error("id,x,y,weight\n", planar_map()).message(), "no sensors");
}

// Vendor exports give projected x/y and lon/lat for each sensor. The pair the map is in
// is used (the oracle: the projection of the lon/lat, or the x/y as written), and a note says so.
TEST(ReportedSensorsCsv, BothPairsGivenThePairOfTheMapIsUsed) {
  const std::string text = "id;x;y;lon;lat;weight\na;1000,5;-200;8,1;47,1;1\nb;30;40;7,9;46,95;2\n";
  std::vector<std::string> notes;
  ReportedSensorOptions geographic = geographic_map();
  geographic.notes = &notes;
  const auto g = csv(text, geographic);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].position.x, swiss().forward(8.1, 47.1).x);
  EXPECT_EQ(g[1].position.y, swiss().forward(7.9, 46.95).y);
  EXPECT_EQ(g[0].lon, 8.1);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "sensors.csv: 2 sensors give both x/y and lon/lat; used lon/lat, as no CRS is declared for x/y (--sensor-crs)");
  notes.clear();
  ReportedSensorOptions planar = planar_map();
  planar.notes = &notes;
  const auto p = csv(text, planar);
  EXPECT_EQ(p[0].position.x, 1000.5);
  EXPECT_EQ(p[1].position.y, 40.0);
  EXPECT_FALSE(p[0].lon.has_value());
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "sensors.csv: 2 sensors give both x/y and lon/lat; used x/y, as the map is planar");
  // The same in covmap.sites/1 JSON, one sensor with both.
  notes.clear();
  const auto j = parse_reported_sensors(R"({"format":"covmap.sites/1","sites":[{"id":"a","x":5,"y":6,"lon":8.1,"lat":47.1,"weight":1},
      {"id":"b","lon":8.2,"lat":47.2,"weight":1}]})", "sensors.json", geographic);
  EXPECT_EQ(j[0].position.x, swiss().forward(8.1, 47.1).x);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "sensors.json: 1 sensor gives both x/y and lon/lat; used lon/lat, as no CRS is declared for x/y (--sensor-crs)");
}

// x/y in a declared CRS (--sensor-crs) go through WGS84 into the map's plane; without a
// declared CRS they are the map's own plane (projected map), refused against a lon/lat map.
TEST(ReportedSensorsCrs, XyInADeclaredCrsArePlacedThroughWgs84) {
  const auto sensor_crs = std::make_shared<ProjectedForTest>(LocalProjection::about(7.0, 46.0));
  const Point xy = sensor_crs->forward(8.1, 47.1);
  const std::string text = "id,x,y,weight\na," + std::to_string(xy.x) + "," + std::to_string(xy.y) + ",1\n";
  ReportedSensorOptions o = geographic_map();
  o.xy_frame = sensor_crs;
  const auto s = csv(text, o);
  const LonLat g = sensor_crs->inverse({std::stod(std::to_string(xy.x)), std::stod(std::to_string(xy.y))});
  EXPECT_EQ(s[0].position.x, swiss().forward(g.lon, g.lat).x);
  EXPECT_EQ(s[0].position.y, swiss().forward(g.lon, g.lat).y);
  EXPECT_NEAR(*s[0].lon, 8.1, 1e-6);
  // Both pairs: with a declared CRS the x/y are used, and the note says in which CRS.
  std::vector<std::string> notes;
  o.notes = &notes;
  csv("id,x,y,lon,lat,weight\na," + std::to_string(xy.x) + "," + std::to_string(xy.y) + ",0,0,1\n", o);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "sensors.csv: 1 sensor gives both x/y and lon/lat; used x/y, in test CRS as declared");
}

TEST(ReportedSensorsCrs, XyWithoutACrsAreTheProjectedMapsPlane) {
  const ProjectedForTest map_crs(LocalProjection::about(7.5, 46.5));
  ReportedSensorOptions o;
  o.frame = &map_crs;
  const auto s = csv("id,x,y,weight\na,1200.5,-300,1\n", o);
  EXPECT_EQ(s[0].position.x, 1200.5);
  EXPECT_EQ(s[0].position.y, -300.0);
  // lon/lat go through the map's CRS.
  const auto g = csv("id,lon,lat,weight\na,7.6,46.4,1\n", o);
  EXPECT_EQ(g[0].position.x, map_crs.forward(7.6, 46.4).x);
  // Against a lon/lat map, x/y without a CRS are refused and the message names --sensor-crs.
  const std::string refused = csv_error("id,x,y,weight\na,1200.5,-300,1\n", geographic_map()).message();
  EXPECT_NE(refused.find("--sensor-crs"), std::string::npos) << refused;
  // x/y in a declared CRS against a map without one cannot be placed.
  ReportedSensorOptions planar = planar_map();
  planar.xy_frame = std::make_shared<ProjectedForTest>(LocalProjection::about(7.0, 46.0));
  const std::string no_map_crs = csv_error("id,x,y,weight\na,1,2,1\n", planar).message();
  EXPECT_NE(no_map_crs.find("the map has no CRS"), std::string::npos) << no_map_crs;
}

// A GeoJSON sensor file that declares a projected CRS at its top: read through the resolver, its
// positions are x/y in that CRS.
TEST(ReportedSensorsCrs, GeoJsonDeclaringACrsIsReadInIt) {
  const auto declared = std::make_shared<ProjectedForTest>(LocalProjection::about(7.0, 46.0));
  ReportedSensorOptions o = geographic_map();
  std::string asked;
  o.resolve_crs = [&](const std::string& name) {
    asked = name;
    return declared;
  };
  const Point xy = declared->forward(8.05, 47.05);
  char text[512];
  std::snprintf(text, sizeof text,
                R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::2056"}},
                    "features":[{"type":"Feature","properties":{"id":"a","weight":1},"geometry":{"type":"Point","coordinates":[%.17g,%.17g]}}]})",
                xy.x, xy.y);
  const auto s = parse_reported_sensors(text, "s.geojson", o);
  EXPECT_EQ(asked, "urn:ogc:def:crs:EPSG::2056");
  const LonLat g = declared->inverse(xy);
  EXPECT_EQ(s[0].position.x, swiss().forward(g.lon, g.lat).x);
  // A resolver that refuses gives the file's error, naming the crs member.
  o.resolve_crs = [](const std::string&) -> std::shared_ptr<const MapFrame> { throw std::invalid_argument("no such CRS"); };
  const InputError e = input_error_from([&] { parse_reported_sensors(text, "s.geojson", o); });
  EXPECT_NE(std::string(e.what()).find("no such CRS"), std::string::npos) << e.what();
}

// ---- JSON (covmap.sites/1) ----

TEST(ReportedSensorsJson, SitesWithOptionalFields) {
  const auto s = parse_reported_sensors(R"({"format":"covmap.sites/1","sites":[
      {"id":"a","x":0,"y":0,"weight":2,"position_sigma_m":3},
      {"id":7,"x":5,"y":1,"tx_power_dbm":20,"power_sigma_db":null}]})",
                                        "sensors.json", [] {
                                          ReportedSensorOptions o;
                                          o.alpha = 2;
                                          return o;
                                        }());
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].weight, 2.0);
  EXPECT_EQ(s[0].position_sigma_m, 3.0);
  EXPECT_EQ(s[1].id, "7");
  EXPECT_DOUBLE_EQ(*s[1].weight, 10.0);
  EXPECT_FALSE(s[1].power_sigma_db.has_value());
  EXPECT_EQ(s[1].origin, "sites[1]");
}

TEST(ReportedSensorsJson, LonLatEntriesAndErrorsNameThePath) {
  const auto s = parse_reported_sensors(R"({"format":"covmap.sites/1","sites":[{"id":"a","lon":8.1,"lat":47.1,"weight":1}]})",
                                        "sensors.json", geographic_map());
  EXPECT_EQ(s[0].lon, 8.1);
  EXPECT_EQ(s[0].position.x, swiss().forward(8.1, 47.1).x);
  const auto e = input_error_from([] {
    parse_reported_sensors(R"({"format":"covmap.sites/1","sites":[{"id":"a","x":1,"lat":2,"weight":1},{"id":"b","x":"1","y":2,"weight":1}]})",
                           "sensors.json", planar_map());
  });
  ASSERT_EQ(e.problems.size(), 2u);
  EXPECT_EQ(e.problems[0].item, "sites[0] (sensor 'a')");
  EXPECT_EQ(e.problems[0].message, "missing y");  // x started, so the x/y pair must be complete
  EXPECT_EQ(e.problems[1].message, "x must be a number (got string \"1\")");
}

// ---- GeoJSON ----

TEST(ReportedSensorsGeoJson, PointsWithIdFromPropertiesOrFeature) {
  const std::string text = R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{"id":"a","tx_power_dbm":35,"position_sigma_m":20},"geometry":{"type":"Point","coordinates":[8.02,47.01,440]}},
      {"type":"Feature","properties":{"sensor":12,"weight":3},"geometry":{"type":"Point","coordinates":[7.98,46.99]}},
      {"type":"Feature","id":"c","properties":{"weight":1},"geometry":{"type":"Point","coordinates":[8.0,47.03]}}]})";
  const auto s = parse_reported_sensors(text, "sensors.geojson", geographic_map(3.5));
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].id, "a");
  EXPECT_DOUBLE_EQ(*s[0].weight, 10.0);
  EXPECT_EQ(s[0].position_sigma_m, 20.0);
  EXPECT_EQ(s[0].position.x, swiss().forward(8.02, 47.01).x);
  EXPECT_EQ(s[1].id, "12");
  EXPECT_EQ(s[2].id, "c");
  EXPECT_EQ(s[2].origin, "features[2]");
  EXPECT_EQ(s[2].lat, 47.03);
}

TEST(ReportedSensorsGeoJson, PlanarAndErrors) {
  ReportedSensorOptions options;
  options.planar = true;
  const auto s = parse_reported_sensors(
      R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"id":"a","weight":1},"geometry":{"type":"Point","coordinates":[512000,5200000]}}]})",
      "s.geojson", options);
  EXPECT_EQ(s[0].position.x, 512000);
  EXPECT_FALSE(s[0].lon.has_value());

  const auto e = input_error_from([] {
    parse_reported_sensors(R"({"type":"FeatureCollection","features":[
        {"type":"Feature","properties":{"weight":1},"geometry":{"type":"Point","coordinates":[8,47]}},
        {"type":"Feature","properties":{"id":"b","weight":1},"geometry":{"type":"Polygon","coordinates":[]}}]})",
                           "s.geojson", geographic_map());
  });
  ASSERT_EQ(e.problems.size(), 2u);
  EXPECT_EQ(e.problems[0].item, "features[0]");
  EXPECT_EQ(e.problems[0].message, "missing id (give properties.id, properties.sensor or the feature's \"id\")");
  EXPECT_EQ(e.problems[1].item, "features[1] (sensor 'b')");
  EXPECT_EQ(e.problems[1].message, "geometry type \"Polygon\" is not supported; a sensor is a Point");
}

TEST(ReportedSensorsGeoJson, ForeignCrs) {
  const auto e = input_error_from([] {
    parse_reported_sensors(R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"EPSG:2056"}},"features":[
        {"type":"Feature","properties":{"id":"a","weight":1},"geometry":{"type":"Point","coordinates":[8,47]}}]})",
                           "s.geojson", geographic_map());
  });
  EXPECT_EQ(e.item(), "crs");
  EXPECT_NE(e.message().find("\"EPSG:2056\""), std::string::npos);
}

// ---- names ----

TEST(ReportedSensorNames, ReadFromEverySyntaxAndEmptyWhenAbsent) {
  // The same three sensors in each syntax: a named one, one with an empty/null name, one without.
  const std::string from_csv = "ID,x,y,weight,NAME\na,0,0,1,\"Bern, Bahnhof\"\nb,1,0,1,\nc,2,0,1\n";
  const std::string from_json = R"({"format":"covmap.sites/1","sites":[
      {"id":"a","name":"Bern, Bahnhof","x":0,"y":0,"weight":1},
      {"id":"b","name":null,"x":1,"y":0,"weight":1},
      {"id":"c","x":2,"y":0,"weight":1}]})";
  const std::string from_geojson = R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{"id":"a","name":"Bern, Bahnhof","weight":1},"geometry":{"type":"Point","coordinates":[0,0]}},
      {"type":"Feature","properties":{"id":"b","name":null,"weight":1},"geometry":{"type":"Point","coordinates":[1,0]}},
      {"type":"Feature","properties":{"id":"c","weight":1},"geometry":{"type":"Point","coordinates":[2,0]}}]})";
  ReportedSensorOptions planar_geojson;
  planar_geojson.planar = true;
  const std::pair<std::string, SensorsFormat> inputs[] = {
      {from_csv, SensorsFormat::kCsv}, {from_json, SensorsFormat::kSitesJson}, {from_geojson, SensorsFormat::kGeoJson}};
  for (const auto& [text, format] : inputs) {
    const auto s = parse_reported_sensors(text, "s", planar_geojson, format);
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].name, "Bern, Bahnhof");
    EXPECT_EQ(s[1].name, "");
    EXPECT_EQ(s[2].name, "");
    EXPECT_EQ(s[0].id, "a");  // the name is a label, never the id
  }
}

TEST(ReportedSensorNames, NonStringNameIsAProblemNamingTheEntry) {
  const auto e = input_error_from([] {
    parse_reported_sensors(R"({"format":"covmap.sites/1","sites":[
        {"id":"a","name":"ok","x":0,"y":0,"weight":1},
        {"id":"b","name":17,"x":1,"y":0,"weight":1}]})",
                           "s.json", planar_map());
  });
  ASSERT_EQ(e.problems.size(), 1u);
  EXPECT_EQ(e.problems[0].item, "sites[1] (sensor 'b')");
  EXPECT_EQ(e.problems[0].message, "name must be a string (got number 17)");

  ReportedSensorOptions planar;
  planar.planar = true;
  const auto g = input_error_from([&] {
    parse_reported_sensors(R"({"type":"FeatureCollection","features":[
        {"type":"Feature","properties":{"id":"a","name":["x"],"weight":1},"geometry":{"type":"Point","coordinates":[0,0]}}]})",
                           "s.geojson", planar);
  });
  ASSERT_EQ(g.problems.size(), 1u);
  EXPECT_EQ(g.problems[0].item, "features[0] (sensor 'a')");
  EXPECT_EQ(g.problems[0].message, "properties.name must be a string (got an array)");
}

TEST(ReportedSensorNames, CsvNameMustBeUtf8) {
  const auto e = csv_error("id,x,y,weight,name\na,0,0,1,Z\xFCrich\n", planar_map());
  ASSERT_EQ(e.problems.size(), 1u);
  EXPECT_EQ(e.problems[0].line, 2);
  EXPECT_EQ(e.problems[0].message, "name is not valid UTF-8");
}

// ---- files ----

TEST(ReportedSensors, ReadsEachFormatByExtension) {
  testing::TempDir dir;
  const auto options = geographic_map(3.0);
  const auto from_csv = read_reported_sensors(dir.write("s.csv", "id,lon,lat,tx_power_dbm\na,8,47.1,30\n"), options);
  const auto from_json = read_reported_sensors(
      dir.write("s.json", R"({"format":"covmap.sites/1","sites":[{"id":"a","lon":8,"lat":47.1,"tx_power_dbm":30}]})"), options);
  const auto from_geojson = read_reported_sensors(
      dir.write("s.geojson", R"({"type":"FeatureCollection","features":[{"type":"Feature","id":"a","properties":{"tx_power_dbm":30},"geometry":{"type":"Point","coordinates":[8,47.1]}}]})"),
      options);
  const auto geojson_in_json = read_reported_sensors(
      dir.write("t.json", R"({"type":"FeatureCollection","features":[{"type":"Feature","id":"a","properties":{"tx_power_dbm":30},"geometry":{"type":"Point","coordinates":[8,47.1]}}]})"),
      options);
  for (const auto* s : {&from_csv, &from_json, &from_geojson, &geojson_in_json}) {
    ASSERT_EQ(s->size(), 1u);
    EXPECT_EQ((*s)[0].id, "a");
    EXPECT_DOUBLE_EQ(*(*s)[0].weight, 10.0);
    EXPECT_EQ((*s)[0].position.y, swiss().forward(8, 47.1).y);
    EXPECT_NEAR((*s)[0].position.y, 11117.0, 1.0);  // 0.1 degree of meridian at 47 N: M * pi / 1800
  }
  // A .json file is JSON even when it is broken: the error is a JSON error, not a CSV header one.
  const auto e = input_error_from([&] { read_reported_sensors(dir.write("bad.json", "[1,"), options); });
  EXPECT_NE(e.message().find("invalid JSON"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace covmap::io
