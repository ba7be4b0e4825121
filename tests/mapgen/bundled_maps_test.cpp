// The sample maps in datasets/maps/ checked against their own truth.json: structure, sizes,
// counts, areas (within the jitter and rounding they were made with), gross-error counts.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/local_projection.h"
#include "tools/mapgen/reported_sensors.h"
#include "mapgen_test_util.h"

namespace covmap::mapgen {
namespace {

using nlohmann::json;
using testing::read_text;
using testing::signed_area;

const std::filesystem::path kMaps = std::filesystem::path(COVMAP_SOURCE_DIR) / "datasets" / "maps";

class BundledMap : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledMap, AgreesWithItsTruth) {
  const auto dir = kMaps / GetParam();
  for (const char* name : {"map.geojson", "sensors.geojson", "truth.json"})
    EXPECT_LT(std::filesystem::file_size(dir / name), 300'000u) << name;
  const json map = json::parse(read_text(dir / "map.geojson"));
  const json sensors = json::parse(read_text(dir / "sensors.geojson"));
  const json truth = json::parse(read_text(dir / "truth.json"));
  ASSERT_EQ(truth["format"], "covmap.mapgen-truth/1");

  const bool lonlat = truth["generator"]["frame"] == "lonlat";
  std::optional<io::LocalProjection> projection;
  if (lonlat) projection = io::LocalProjection::about(truth["projection"]["lon0"], truth["projection"]["lat0"]);
  const auto plane = [&](const json& position) {
    const Point p{position[0].get<double>(), position[1].get<double>()};
    return lonlat ? projection->forward(p.x, p.y) : p;
  };

  // Sensors: the reported list names the true sensors in order, with the stated sigmas.
  const json& truth_sensors = truth["sensors"];
  const std::size_t n = truth_sensors.size();
  ASSERT_EQ(sensors["features"].size(), n);
  std::map<std::string, std::size_t> index;
  std::size_t gross = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const json& t = truth_sensors[k];
    const json& r = sensors["features"][k];
    index[t["id"]] = k;
    EXPECT_EQ(r["properties"]["id"], t["id"]);
    EXPECT_EQ(r["properties"]["tx_power_dbm"], t["reported"]["tx_power_dbm"]);
    EXPECT_EQ(r["properties"]["position_sigma_m"], truth["generator"]["position_sigma_m"]);
    const double alpha = truth["generator"]["alpha"], p0 = truth["generator"]["reference_power_dbm"];
    EXPECT_NEAR(t["tx_power_dbm"].get<double>(), 10 * alpha * std::log10(t["weight"].get<double>()) + p0, 1e-9);
    EXPECT_LE(t["weight"].get<double>(), 1.0);
    if (!t["gross_error"].is_null()) ++gross;
    if (lonlat) {  // the true lon/lat and plane position describe the same point
      const Point p = projection->forward(t["lon"].get<double>(), t["lat"].get<double>());
      EXPECT_NEAR(p.x, t["x"].get<double>(), 1e-3);
      EXPECT_NEAR(p.y, t["y"].get<double>(), 1e-3);
    }
  }
  EXPECT_EQ(gross, gross_error_count(n, truth["generator"]["gross_fraction"].get<double>()));
  EXPECT_EQ(truth["counts"]["gross_errors"].get<std::size_t>(), gross);

  // Cells: every feature names a known sensor once; areas match the bin counts.
  const double bin = truth["raster"]["bin_size_m"];
  // Jitter and rounding move the boundary by far less than their size on average; allow that much.
  const double slack_per_metre = truth["generator"]["vertex_jitter_m"].get<double>() + 0.1;
  std::set<std::string> seen;
  std::size_t cells = 0, holes = 0, vertices = 0;
  for (const json& feature : map["features"]) {
    const std::string id = feature["properties"]["sensor"];
    ASSERT_TRUE(index.count(id)) << id;
    EXPECT_TRUE(seen.insert(id).second) << "one feature per sensor: " << id;
    const json& t = truth_sensors[index[id]];
    const json& geometry = feature["geometry"];
    const json polygons = geometry["type"] == "Polygon" ? json::array({geometry["coordinates"]}) : geometry["coordinates"];
    EXPECT_EQ(geometry["type"] == "MultiPolygon", t["cells"].get<std::size_t>() > 1);
    EXPECT_EQ(polygons.size(), t["cells"].get<std::size_t>());
    double area = 0.0, perimeter = 0.0;
    for (const json& polygon : polygons) {
      ++cells;
      holes += polygon.size() - 1;
      for (std::size_t k = 0; k < polygon.size(); ++k) {
        std::vector<Point> ring;
        for (const json& v : polygon[k]) ring.push_back(plane(v));
        ASSERT_GE(ring.size(), 5u);
        EXPECT_EQ(polygon[k].front(), polygon[k].back()) << "closed ring";
        vertices += ring.size() - 1;
        const double a = signed_area(ring);
        EXPECT_TRUE(k == 0 ? a > 0 : a < 0) << id << ": outer counter-clockwise, holes clockwise";
        area += a;
        for (std::size_t v = 0; v + 1 < ring.size(); ++v) perimeter += std::hypot(ring[v + 1].x - ring[v].x, ring[v + 1].y - ring[v].y);
      }
    }
    EXPECT_NEAR(area, t["bins"].get<double>() * bin * bin, slack_per_metre * perimeter) << id;
  }
  EXPECT_EQ(seen.size(), n - truth["counts"]["sensors_without_bins"].get<std::size_t>());
  EXPECT_EQ(cells, truth["counts"]["cells"].get<std::size_t>());
  EXPECT_EQ(holes, truth["counts"]["holes"].get<std::size_t>());
  EXPECT_EQ(vertices, truth["counts"]["vertices"].get<std::size_t>());
}

INSTANTIATE_TEST_SUITE_P(Maps, BundledMap, ::testing::Values("bern", "ticino", "switzerland"));

// The town list's name column, read here by hand (the oracle): id -> name.
std::map<std::string, std::string> town_names(const std::filesystem::path& csv) {
  std::istringstream lines(read_text(csv));
  std::map<std::string, std::string> names;
  std::vector<std::string> header;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string field; std::getline(cells, field, ',');) fields.push_back(field);
    if (header.empty()) {
      header = fields;
      continue;
    }
    const auto column = [&](const std::string& name) { return fields.at(std::find(header.begin(), header.end(), name) - header.begin()); };
    names[column("id")] = column("name");
  }
  return names;
}

TEST(BundledMaps, BernSensorsCarryTheirTownNamesInEveryFile) {
  const auto names = town_names(kMaps / "bern_towns.csv");
  const json map = json::parse(read_text(kMaps / "bern" / "map.geojson"));
  const json sensors = json::parse(read_text(kMaps / "bern" / "sensors.geojson"));
  const json truth = json::parse(read_text(kMaps / "bern" / "truth.json"));
  ASSERT_EQ(truth["sensors"].size(), names.size());
  for (const json& t : truth["sensors"]) EXPECT_EQ(t["name"], names.at(t["id"]));
  for (const json& f : sensors["features"]) EXPECT_EQ(f["properties"]["name"], names.at(f["properties"]["id"]));
  for (const json& f : map["features"]) EXPECT_EQ(f["properties"]["name"], names.at(f["properties"]["sensor"]));
  EXPECT_EQ(names.at("2657913"), "Zollikofen");  // the list's first town, as GeoNames spells it
}

TEST(BundledMaps, TotalSizeUnderOneMegabyte) {
  std::uintmax_t total = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kMaps))
    if (entry.is_regular_file()) total += entry.file_size();
  EXPECT_LT(total, 1'000'000u);
}

}  // namespace
}  // namespace covmap::mapgen
