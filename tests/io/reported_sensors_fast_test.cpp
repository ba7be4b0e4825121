// The reported sensors' GeoJSON fast path (io/reported_sensors_parsers.h) against the reference
// reader as the oracle. The contract: whenever the fast path takes a text, the reference makes the
// identical drafts (numbers bit for bit), file problems and declared CRS from it; whenever it
// misses, the public reader's answer is the reference's, errors included.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "coverage_map_test_util.h"
#include "io/local_projection.h"
#include "io/reported_sensors_parsers.h"
#include "io_test_util.h"

namespace covmap::io {
namespace {

using detail::SensorDraft;
using testing::bits;
using testing::mutate_all;
using testing::OrderedJson;

std::string optional_bits(const std::optional<double>& v) { return v ? bits(*v) : "-"; }

// A first pass's outcome as text: the drafts, the file problems and whether a CRS was declared.
std::string fingerprint(const std::vector<SensorDraft>& drafts, const std::vector<InputProblem>& file_problems,
                        const std::shared_ptr<const MapFrame>& declared) {
  std::string out = declared ? "declared\n" : "";
  for (const InputProblem& p : file_problems) out += "file problem " + p.item + ": " + p.message + "\n";
  for (const SensorDraft& d : drafts) {
    const ReportedSensor& s = d.sensor;
    out += s.origin + " id " + s.id + " name " + s.name + " weight " + optional_bits(s.weight) + " power " +
           optional_bits(s.tx_power_dbm) + " sigmas " + optional_bits(s.position_sigma_m) + " " +
           optional_bits(s.power_sigma_db) + " line " + std::to_string(d.line);
    if (d.xy) out += " xy " + bits(d.xy->x) + "," + bits(d.xy->y);
    if (d.lon_lat) out += " lonlat " + bits(d.lon_lat->lon) + "," + bits(d.lon_lat->lat);
    out += "\n";
    for (const auto& problem : d.problems) out += "  problem " + problem + "\n";
  }
  return out;
}

std::string describe(const std::vector<ReportedSensor>& sensors) {
  std::string out;
  for (const ReportedSensor& s : sensors)
    out += s.id + " " + s.name + " " + bits(s.position.x) + "," + bits(s.position.y) + " " + optional_bits(s.weight) + " " +
           optional_bits(s.lon) + " " + optional_bits(s.lat) + " " + s.origin + "\n";
  return out;
}

// The public reader's answer: the sensors, or the error as the user sees it.
std::string outcome(const std::string& text, const ReportedSensorOptions& options) {
  try {
    return describe(parse_reported_sensors(text, "s.geojson", options, SensorsFormat::kGeoJson));
  } catch (const InputError& e) {
    return std::string("error: ") + e.what();
  }
}

// The same answer through the reference alone (as the public reader did before the fast path).
std::string reference_outcome(const std::string& text, const ReportedSensorOptions& options) {
  try {
    std::shared_ptr<const MapFrame> declared;
    std::vector<InputProblem> problems;
    std::vector<SensorDraft> drafts =
        detail::parse_sensors_geojson(detail::parse_json(text, "s.geojson"), "s.geojson", options.planar,
                                      options.xy_frame != nullptr, options.resolve_crs, declared, problems);
    const MapFrame* xy_frame = options.xy_frame ? options.xy_frame.get() : declared.get();
    return describe(detail::finish_sensors(std::move(drafts), "s.geojson", options, xy_frame, std::move(problems)));
  } catch (const InputError& e) {
    return std::string("error: ") + e.what();
  }
}

// True when the fast path took the text; then the reference must agree exactly.
bool fast_path_agrees(const std::string& text, const ReportedSensorOptions& options) {
  const bool xy_crs = options.xy_frame != nullptr;
  std::shared_ptr<const MapFrame> declared;
  std::vector<InputProblem> file_problems;
  const auto fast = detail::parse_sensors_geojson_fast(text, options.planar, xy_crs, options.resolve_crs, declared, file_problems);
  if (!fast) {
    EXPECT_TRUE(!declared && file_problems.empty()) << "a miss must leave the outputs alone";
    return false;
  }
  std::shared_ptr<const MapFrame> reference_declared;
  std::vector<InputProblem> reference_problems;
  std::vector<SensorDraft> reference;
  EXPECT_NO_THROW(reference = detail::parse_sensors_geojson(detail::parse_json(text, "s"), "s", options.planar, xy_crs,
                                                            options.resolve_crs, reference_declared, reference_problems))
      << text;
  EXPECT_EQ(fingerprint(*fast, file_problems, declared), fingerprint(reference, reference_problems, reference_declared)) << text;
  return true;
}

ReportedSensorOptions planar() {
  ReportedSensorOptions options;
  options.planar = true;
  options.alpha = 3.5;
  return options;
}

ReportedSensorOptions lon_lat() {
  static const LocalProjection projection = LocalProjection::about(8.0, 47.0);
  ReportedSensorOptions options;
  options.frame = &projection;
  options.alpha = 3.5;
  return options;
}

OrderedJson point(double a, double b) { return {{"type", "Point"}, {"coordinates", {a, b}}}; }

// As covmap-make-map writes them, with the other ways of naming a sensor and an altitude.
OrderedJson sensors() {
  OrderedJson features = OrderedJson::array();
  features.push_back({{"type", "Feature"},
                      {"properties", {{"id", "r1"}, {"name", "Zürich"}, {"tx_power_dbm", 31.5}, {"weight", 0.454},
                                      {"position_sigma_m", 20.0}, {"power_sigma_db", 1.0}}},
                      {"geometry", point(8.1, 47.05)}});
  features.push_back({{"type", "Feature"}, {"properties", {{"sensor", 17}, {"weight", 2}, {"name", nullptr}}}, {"geometry", point(8.2, 47.0)}});
  OrderedJson third = {{"type", "Feature"}, {"id", "f3"}, {"properties", nullptr}, {"geometry", point(8.0, 46.9)}};
  third["geometry"]["coordinates"].push_back(540.5);
  features.push_back(third);
  return {{"type", "FeatureCollection"}, {"features", features}};
}

TEST(ReportedSensorsFast, WritersLayoutsTakeTheFastPathAndAgree) {
  for (const int indent : {-1, 2}) {
    EXPECT_TRUE(fast_path_agrees(sensors().dump(indent), lon_lat()));
    EXPECT_TRUE(fast_path_agrees(nlohmann::json::parse(sensors().dump()).dump(indent), lon_lat()));  // sorted members
    EXPECT_TRUE(fast_path_agrees(sensors().dump(indent), planar()));
  }
}

TEST(ReportedSensorsFast, MutatedFilesEitherMissOrAgree) {
  OrderedJson small = {{"type", "FeatureCollection"},
                       {"crs", {{"type", "name"}, {"properties", {{"name", "EPSG:4326"}}}}},
                       {"features",
                        {{{"type", "Feature"},
                          {"id", 3},
                          {"properties", {{"id", nullptr}, {"name", "a"}, {"weight", 1.5}}},
                          {"geometry", point(8.1, 47.0)}},
                         {{"type", "Feature"}, {"properties", {{"sensor", "b"}, {"tx_power_dbm", -3}}}, {"geometry", point(8, 47)}}}}};
  for (const auto& options : {lon_lat(), planar()}) {
    const auto [taken, missed] = mutate_all(small.dump(), [&](const std::string& text) {
      // Taken or not, the public reader answers as the reference does.
      EXPECT_EQ(outcome(text, options), reference_outcome(text, options)) << text;
      return fast_path_agrees(text, options);
    });
    EXPECT_GT(taken, 100);
    EXPECT_GT(missed, 1000);
  }
}

TEST(ReportedSensorsFast, UnusualOrWrongInputIsLeftToTheReference) {
  const std::string good = sensors().dump();
  const auto variant = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  for (const std::string& text : {variant(R"("id":"r1")", R"("id":"")"), variant(R"("id":"r1")", R"("id":1.5)"),
                                  variant(R"("id":"r1")", R"("id":"r1","id":"r2")"), variant(R"("weight":2)", R"("weight":"2")"),
                                  variant(R"("name":"Zürich")", R"("name":7)"), variant(R"("type":"Point")", R"("type":"LineString")"),
                                  variant("[8.1,47.05]", "[8.1]"), variant(R"("id":"f3",)", ""), variant("8.1,", "1e999,"),
                                  variant(R"("type":"FeatureCollection",)", R"("type":"FeatureCollection","format":"x",)"),
                                  good.substr(0, good.size() - 3), std::string(R"({"type":"FeatureCollection","features":[]})")}) {
    std::shared_ptr<const MapFrame> declared;
    std::vector<InputProblem> problems;
    EXPECT_FALSE(detail::parse_sensors_geojson_fast(text, false, false, {}, declared, problems)) << text;
  }
  // A duplicate id is a problem of the rest of the reader: taken, and worded as before.
  const std::string duplicate = variant(R"("sensor":17)", R"("sensor":"r1")");
  EXPECT_TRUE(fast_path_agrees(duplicate, lon_lat()));
  EXPECT_EQ(outcome(duplicate, lon_lat()), reference_outcome(duplicate, lon_lat()));
  EXPECT_NE(outcome(duplicate, lon_lat()).find("duplicate id"), std::string::npos);
}

TEST(ReportedSensorsFast, DeclaredCrsIsResolvedAsTheReferenceResolvesIt) {
  OrderedJson swiss = sensors();
  swiss["crs"] = {{"type", "name"}, {"properties", {{"name", "EPSG:2056"}}}};
  swiss["features"][1]["crs"] = {{"type", "name"}, {"properties", {{"name", "EPSG:2056"}}}};
  ReportedSensorOptions options = lon_lat();
  options.resolve_crs = [](const std::string& name) -> std::shared_ptr<const MapFrame> {
    if (name != "EPSG:2056") throw std::invalid_argument("unknown CRS " + name);
    return std::make_shared<testing::ProjectedForTest>(LocalProjection::about(7.4, 46.9));
  };
  EXPECT_TRUE(fast_path_agrees(swiss.dump(), options));
  EXPECT_EQ(outcome(swiss.dump(), options), reference_outcome(swiss.dump(), options));
  swiss["crs"]["properties"]["name"] = "EPSG:99999";  // refused by the resolver: a file problem
  EXPECT_TRUE(fast_path_agrees(swiss.dump(), options));
  EXPECT_EQ(outcome(swiss.dump(), options), reference_outcome(swiss.dump(), options));
  EXPECT_TRUE(fast_path_agrees(swiss.dump(), planar()));
}

}  // namespace
}  // namespace covmap::io
