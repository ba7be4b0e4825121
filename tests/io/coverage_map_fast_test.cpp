// The coverage-map reader's fast first pass (io/coverage_map_drafts.h) against the reference as
// the oracle. The contract: whenever the fast path takes a text, the reference makes the identical
// drafts from it, and the whole reader then gives the identical map or the identical error;
// whenever it misses, the public reader's answer is the reference's. Writers' usual layouts take
// the fast path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>
#include <utility>

#include "coverage_map_test_util.h"
#include "io/coverage_map_drafts.h"
#include "io_test_util.h"

namespace covmap::io {
namespace {

using Json = nlohmann::json;
using detail::FeatureDrafts;
using detail::read_features_fast;
using detail::read_features_reference;
using testing::append_ring;
using testing::feature;
using testing::fingerprint;
using testing::mutate_all;
using testing::OrderedJson;
using testing::outcome;
using testing::square;

constexpr const char* kFile = "map.geojson";

// ---- comparing ----

// The drafts as text, numbers by their bits (as testing::fingerprint of a map).
std::string fingerprint(const FeatureDrafts& first) {
  std::string out;
  for (const auto& d : first.drafts) {
    out += std::to_string(d.index) + " " + d.label + " sensor " + d.sensor + " name " + d.name + (d.multi ? " multi" : "") + "\n";
    for (const auto& polygon : d.polygons) {
      for (const auto& ring : polygon) append_ring(out, ring);
      out += "\n";
    }
    for (const auto& problem : d.problems) out += "problem " + problem + "\n";
  }
  for (const bool any_system : {false, true})
    for (const InputProblem& p : first.crs.problems(any_system)) out += "crs " + p.item + ": " + p.message + "\n";
  out += "top " + first.crs.foreign_top_level().value_or("-") + (first.top.frame ? " resolved" : "") + "\n";
  for (const InputProblem& p : first.top.problems) out += "top problem " + p.item + ": " + p.message + "\n";
  return out;
}

// True when the fast path took the text; then the reference must make the same drafts, and both
// must end in the same map or error. Either way the public reader must answer as the reference.
bool fast_path_agrees(const std::string& text, const CoverageMapOptions& options = {}) {
  const std::string reference = outcome([&] { return detail::finish_coverage_map(read_features_reference(text, kFile, options), kFile, options); });
  EXPECT_EQ(outcome([&] { return parse_coverage_map(text, kFile, options); }), reference) << text;
  auto fast = read_features_fast(text, options);
  if (!fast) return false;
  FeatureDrafts from_reference;
  EXPECT_NO_THROW(from_reference = read_features_reference(text, kFile, options)) << text;
  EXPECT_EQ(fingerprint(*fast), fingerprint(from_reference)) << text;
  EXPECT_EQ(outcome([&] { return detail::finish_coverage_map(std::move(*fast), kFile, options); }), reference) << text;
  return true;
}

CoverageMapOptions planar() {
  CoverageMapOptions options;
  options.planar = true;
  return options;
}

// ---- maps as writers lay them out ----

// A lon/lat map with a hole, a MultiPolygon, an integer sensor, names and an altitude.
OrderedJson lon_lat_map() {
  OrderedJson hole = OrderedJson::array({{7.42, 46.92}, {7.42, 46.94}, {7.44, 46.94}, {7.44, 46.92}, {7.42, 46.92}});
  OrderedJson multi = {{"type", "MultiPolygon"},
                       {"coordinates", {{square(7.5, 46.9, 0.05)}, {square(7.6, 46.9, 0.01)}}}};
  OrderedJson with_altitude = square(7.4, 47.0, 0.05);
  with_altitude[1].push_back(512.5);
  return {{"type", "FeatureCollection"},
          {"features",
           {feature("bern", {{"type", "Polygon"}, {"coordinates", {square(7.4, 46.9, 0.05), hole}}}, "Bern Zähringer"),
            feature(17, multi), feature("c", {{"type", "Polygon"}, {"coordinates", {with_altitude}}})}}};
}

OrderedJson planar_map() {
  OrderedJson map = {{"type", "FeatureCollection"},
                     {"crs", {{"type", "name"}, {"properties", {{"name", "covmap:local-plane-metres"}}}}},
                     {"features",
                      {feature("a", {{"type", "Polygon"}, {"coordinates", {square(0, 0, 1000)}}}),
                       feature("b", {{"type", "Polygon"}, {"coordinates", {square(1000, 0, 1000.5)}}})}}};
  return map;
}

TEST(CoverageMapFast, WritersLayoutsTakeTheFastPathAndAgree) {
  for (const int indent : {-1, 2}) {
    EXPECT_TRUE(fast_path_agrees(lon_lat_map().dump(indent)));
    EXPECT_TRUE(fast_path_agrees(planar_map().dump(indent), planar()));
    // nlohmann::json sorts member names: "coordinates" before "type", "features" before "type".
    EXPECT_TRUE(fast_path_agrees(Json::parse(lon_lat_map().dump()).dump(indent)));
    EXPECT_TRUE(fast_path_agrees(Json::parse(planar_map().dump()).dump(indent), planar()));
  }
}

TEST(CoverageMapFast, MutatedMapsEitherMissOrAgree) {
  // Small maps keep the variants (about 35 per byte) manageable; a hole, a MultiPolygon, a name
  // and a crs put every member the fast path reads within reach of a mutation.
  OrderedJson lon_lat = {{"type", "FeatureCollection"},
                         {"features",
                          {feature("a", {{"type", "Polygon"}, {"coordinates", {square(8, 47, 1), square(8.2, 47.2, 0.1)}}}, "n"),
                           feature(7, {{"type", "MultiPolygon"}, {"coordinates", {{square(9, 47, 0.5)}}}})}}};
  const auto [taken, missed] = mutate_all(lon_lat.dump(), [](const std::string& t) { return fast_path_agrees(t); });
  EXPECT_GT(taken, 100);
  EXPECT_GT(missed, 1000);
  OrderedJson crs = {{"type", "FeatureCollection"},
                     {"features",
                      {{{"type", "Feature"},
                        {"crs", nullptr},
                        {"properties", {{"sensor", "a"}}},
                        {"geometry", {{"type", "Polygon"}, {"coordinates", {square(0, 0, 10)}}, {"crs", {{"type", "name"}}}}}}}},
                     {"crs", {{"type", "name"}, {"properties", {{"name", "EPSG:2056"}}}}}};
  const auto [crs_taken, crs_missed] =
      mutate_all(crs.dump(), [](const std::string& t) { return fast_path_agrees(t, planar()); });
  EXPECT_GT(crs_taken, 50);
  EXPECT_GT(crs_missed, 500);
}

TEST(CoverageMapFast, CrsDeclarationsAreJudgedAsTheReferenceJudgesThem) {
  // Declarations on the collection (after the features), a feature and a geometry: with --planar
  // only their disagreement is a problem, without it the foreign one is; the fast path keeps the
  // reference's order and paths either way.
  // A planning tool's own label (covmap's own plane would make the positions planar by itself).
  OrderedJson map = planar_map();
  map["crs"]["properties"]["name"] = "planner:own-plane";
  map["features"][0]["crs"] = {{"type", "name"}, {"properties", {{"name", "EPSG:4326"}}}};
  map["features"][1]["geometry"]["crs"] = {{"type", "EPSG"}, {"properties", {{"code", 2056}}}};
  const OrderedJson top = map["crs"];
  map.erase("crs");
  map["crs"] = top;
  EXPECT_TRUE(fast_path_agrees(map.dump(), planar()));
  // Without --planar the positions are read as lon/lat, out of range: the reference words that.
  EXPECT_FALSE(fast_path_agrees(map.dump()));
  // A resolver: the top-level CRS becomes the map's frame, positions are x/y in it.
  CoverageMapOptions resolving;
  resolving.resolve_crs = [](const std::string& name) -> std::shared_ptr<const MapFrame> {
    if (name != "EPSG:2056") throw std::invalid_argument("unknown CRS " + name);
    return std::make_shared<testing::ProjectedForTest>(LocalProjection::about(7.4, 46.9));
  };
  OrderedJson swiss = planar_map();
  swiss["crs"]["properties"]["name"] = "EPSG:2056";
  EXPECT_TRUE(fast_path_agrees(swiss.dump(), resolving));
  OrderedJson label = planar_map();
  label["crs"]["properties"]["name"] = "planner:own-plane";
  EXPECT_TRUE(fast_path_agrees(label.dump(), resolving));  // refused by the resolver: reported once
  // covmap's own plane is never handed to the resolver: the positions are planar metres.
  EXPECT_TRUE(fast_path_agrees(planar_map().dump(), resolving));
  EXPECT_TRUE(fast_path_agrees(planar_map().dump()));
}

TEST(CoverageMapFast, NumbersAreReadAsTheReferenceReadsThem) {
  // Exponents, "-0" (an integer token: +0), "-0.0", subnormals, long mantissas: all taken, and the
  // drafts compared bit for bit. (Integers beyond 64 bits are beyond every coordinate limit.)
  for (const char* x : {"-0", "-0.0", "1E-2", "4.9e-324", "0.1e1", "-1.5e-3", "0.30000000000000004", "123456789e-9"}) {
    const std::string text = std::string(R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"sensor":"a"},)") +
                             R"("geometry":{"type":"Polygon","coordinates":[[[)" + x + R"(,0],[1000,0],[1000,1000],[)" + x + "," +
                             R"(0]]]}}]})";
    EXPECT_TRUE(fast_path_agrees(text, planar())) << x;
  }
}

TEST(CoverageMapFast, UnusualOrWrongInputIsLeftToTheReference) {
  const std::string good = planar_map().dump();
  const auto variant = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  const std::string misses[] = {
      variant(R"("sensor":"a")", R"("sensor":"\u0061")"),                          // \u escape
      variant(R"("sensor":"a")", R"("sensor":"a","sensor":"b")"),                  // repeated member
      variant(R"("sensor":"a")", R"("sensor":1.5)"),                               // not an id
      variant(R"("sensor":"a")", R"("name":"a")"),                                 // no sensor
      variant(R"("sensor":"a")", R"("sensor":"a","name":3)"),                      // name not a string
      variant("[1000.0,0.0]", "[1e999,0.0]"),                                      // overflow
      variant("[1000.0,0.0]", "[1e9,0.0]"),                                        // beyond the planar limit
      variant("[1000.0,0.0]", "[1000.0]"),                                         // half a position
      variant("[0.0,1000.0],[0.0,0.0]]", "[0.0,1000.0],[0.0,1.0]]"),               // ring not closed
      variant(R"("type":"Polygon")", R"("type":"LineString")"),                    // wrong geometry
      variant(R"("type":"Feature")", R"("type":"Feat")"),                          // not a feature
      variant(R"("features":[)", R"("features":[],"x":[)"),                        // no features
      "\xEF\xBB\xBF" + good,                                                       // byte order mark
      good.substr(0, good.size() / 2),                                             // truncated
  };
  for (const std::string& text : misses) {
    EXPECT_FALSE(read_features_fast(text, planar())) << text;
    EXPECT_FALSE(fast_path_agrees(text, planar())) << text;
  }
  // A self-crossing ring is a second-pass problem: the fast path takes the text, and the error is
  // the reference's all the same.
  const std::string crossing = variant("[1000.0,0.0],[1000.0,1000.0]", "[1000.0,1000.0],[1000.0,0.0]");
  EXPECT_TRUE(fast_path_agrees(crossing, planar()));
  EXPECT_NE(outcome([&] { return parse_coverage_map(crossing, kFile, planar()); }).find("crosses itself"), std::string::npos);
}

TEST(CoverageMapFast, RawUtf8PropertyNamesAndOtherSensorProperty) {
  OrderedJson map = lon_lat_map();
  for (auto& f : map["features"]) {
    f["properties"]["Höhe"] = 12;
    f["properties"]["site"] = f["properties"]["sensor"];
  }
  EXPECT_TRUE(fast_path_agrees(map.dump()));
  CoverageMapOptions by_site;
  by_site.sensor_property = "site";
  EXPECT_TRUE(fast_path_agrees(map.dump(), by_site));
  CoverageMapOptions by_name;
  by_name.sensor_property = "name";
  EXPECT_FALSE(fast_path_agrees(map.dump(), by_name));  // feature 17 has no name: the reference says so
}

}  // namespace
}  // namespace covmap::io
