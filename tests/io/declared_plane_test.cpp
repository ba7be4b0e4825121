// covmap reads what it writes: GeoJSON that declares covmap's own plane (io::kPlaneCrsName, as
// covmap-make-map writes planar maps and sensors) is read as planar metres without --planar,
// exactly as --planar reads it; without that declaration the same numbers are no lon/lat.
#include <gtest/gtest.h>

#include <string>

#include "io/coverage_map.h"
#include "io/input_error.h"
#include "io/map_frame.h"
#include "io/reported_sensors.h"

namespace covmap::io {
namespace {

std::string collection(const std::string& crs_name, const std::string& features) {
  const std::string crs = crs_name.empty() ? "" : R"("crs":{"type":"name","properties":{"name":")" + crs_name + R"("}},)";
  return R"({"type":"FeatureCollection",)" + crs + R"("features":[)" + features + "]}";
}

const std::string kCells =
    R"({"type":"Feature","properties":{"sensor":"a"},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1000,0],[1000,1000],[0,1000],[0,0]]]}},)"
    R"({"type":"Feature","properties":{"sensor":"b"},"geometry":{"type":"Polygon","coordinates":[[[1000,0],[2500,0],[2500,1000],[1000,1000],[1000,0]]]}})";
const std::string kSensors =
    R"({"type":"Feature","properties":{"id":"a","weight":1},"geometry":{"type":"Point","coordinates":[500,400]}},)"
    R"({"type":"Feature","properties":{"id":"b","weight":2},"geometry":{"type":"Point","coordinates":[1800,600]}})";

TEST(DeclaredPlane, AMapInCovmapsPlaneReadsAsWithPlanar) {
  const std::string text = collection(std::string(kPlaneCrsName), kCells);
  CoverageMapOptions planar;
  planar.planar = true;
  const CoverageMap declared = parse_coverage_map(text, "map.geojson", {});
  const CoverageMap forced = parse_coverage_map(text, "map.geojson", planar);
  EXPECT_EQ(declared.frame, nullptr);
  ASSERT_EQ(declared.cells.size(), 2u);
  ASSERT_EQ(declared.cells.size(), forced.cells.size());
  for (std::size_t i = 0; i < declared.cells.size(); ++i) {
    EXPECT_EQ(declared.cells[i].sensor, forced.cells[i].sensor);
    ASSERT_EQ(declared.cells[i].polygons.size(), forced.cells[i].polygons.size());
    const auto& a = declared.cells[i].polygons[0].outer;  // the metres as written
    const auto& b = forced.cells[i].polygons[0].outer;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(a[k].x == b[k].x && a[k].y == b[k].y);
  }
  EXPECT_EQ(declared.cells[1].polygons[0].outer.front().x, 1000.0);
  // Another name is a CRS covmap cannot read as lon/lat, and undeclared metres are no lon/lat.
  EXPECT_THROW(parse_coverage_map(collection("covmap:some-other-plane", kCells), "map.geojson", {}), InputError);
  EXPECT_THROW(parse_coverage_map(collection("", kCells), "map.geojson", {}), InputError);
}

TEST(DeclaredPlane, SensorsInCovmapsPlaneReadAsWithPlanar) {
  ReportedSensorOptions planar;
  planar.planar = true;
  const auto declared = parse_reported_sensors(collection(std::string(kPlaneCrsName), kSensors), "s.geojson", {});
  const auto forced = parse_reported_sensors(collection(std::string(kPlaneCrsName), kSensors), "s.geojson", planar);
  ASSERT_EQ(declared.size(), 2u);
  for (std::size_t i = 0; i < declared.size(); ++i) {
    EXPECT_EQ(declared[i].position.x, forced[i].position.x);
    EXPECT_EQ(declared[i].position.y, forced[i].position.y);
    EXPECT_FALSE(declared[i].lon);
  }
  EXPECT_EQ(declared[1].position.x, 1800.0);
}

}  // namespace
}  // namespace covmap::io
