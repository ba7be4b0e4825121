// Bounded input: nesting, planar coordinates and counts beyond io/input_limits.h are
// refused with an InputError naming the limit, before any work that grows with them.
#include "io/input_limits.h"

#include <gtest/gtest.h>

#include <string>

#include "io/coverage_map.h"
#include "io/diagram_json.h"
#include "io/input_error.h"
#include "io/reported_sensors.h"
#include "io/sites_io.h"

namespace covmap::io {
namespace {

std::string nested(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// 200 000 levels once crashed the error message (the JSON library prints recursively).
TEST(InputLimits, DeepNestingIsRefusedInEveryJsonReader) {
  const std::string deep = nested(200000);
  const std::string map = R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"sensor":"a"},)"
                          R"("geometry":{"type":"Polygon","coordinates":)" + deep + "}}]}";
  const std::string crs = R"({"type":"FeatureCollection","crs":)" + deep + R"(,"features":[]})";
  const std::string sites = R"({"format":"covmap.sites/1","sites":)" + deep + "}";
  for (const std::string& message :
       {error_of([&] { parse_coverage_map(map, "m.geojson"); }), error_of([&] { parse_coverage_map(crs, "c.geojson"); }),
        error_of([&] { parse_sites(sites, "s.json", SitesFormat::kJson); }),
        error_of([&] { parse_reported_sensors(sites, "r.json", {}, SensorsFormat::kSitesJson); }),
        error_of([&] { parse_diagram_json("{\"format\":\"covmap.arcgraph/1\",\"nodes\":" + deep + "}", "g.json"); })}) {
    EXPECT_NE(message.find("nested more than 32 levels"), std::string::npos) << message.substr(0, 300);
  }
}

TEST(InputLimits, NestingAtTheLimitAndBracketsInStringsAreFine) {
  // 32 levels parse (and then fail for what they are, not for depth); brackets inside strings do
  // not count.
  const std::string at_limit = R"({"format":"covmap.sites/1","sites":)" + nested(31) + "}";
  EXPECT_EQ(error_of([&] { parse_sites(at_limit, "s.json", SitesFormat::kJson); }).find("nested"), std::string::npos);
  const std::string in_strings = R"({"format":"covmap.sites/1","sites":[{"id":")" + std::string(100, '[') +
                                 R"(","x":0,"y":0,"weight":1}]})";
  EXPECT_EQ(parse_sites(in_strings, "s.json", SitesFormat::kJson).sites.size(), 1u);
}

TEST(InputLimits, PlanarCoordinatesBeyondAnyCrsAreRefusedOncePerFeature) {
  const std::string map = R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"sensor":"a"},)"
                          R"("geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,2147483648],[0,10],[0,0]]]}}]})";
  CoverageMapOptions planar;
  planar.planar = true;
  const std::string message = error_of([&] { parse_coverage_map(map, "m.geojson", planar); });
  EXPECT_NE(message.find("features[0]"), std::string::npos) << message;
  EXPECT_NE(message.find("mistyped"), std::string::npos) << message;
}

TEST(InputLimits, TooManyFeaturesAreRefusedBeforeTheGeometryIsRead) {
  std::string map = R"({"type":"FeatureCollection","features":[)";
  for (std::size_t i = 0; i <= kMaxMapFeatures; ++i) map += i ? ",0" : "0";
  map += "]}";
  const std::string message = error_of([&] { parse_coverage_map(map, "m.geojson"); });
  EXPECT_NE(message.find("at most " + std::to_string(kMaxMapFeatures)), std::string::npos) << message.substr(0, 300);
}

TEST(InputLimits, TooManyReportedSensorsAreRefused) {
  std::string csv = "id,x,y,weight\n";
  for (std::size_t i = 0; i <= kMaxReportedSensors; ++i) csv += "s" + std::to_string(i) + "," + std::to_string(i) + ",0,1\n";
  ReportedSensorOptions planar;
  planar.planar = true;
  const std::string message = error_of([&] { parse_reported_sensors(csv, "r.csv", planar, SensorsFormat::kCsv); });
  EXPECT_NE(message.find("at most " + std::to_string(kMaxReportedSensors)), std::string::npos) << message.substr(0, 300);
}

}  // namespace
}  // namespace covmap::io
