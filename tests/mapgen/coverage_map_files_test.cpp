#include "tools/mapgen/coverage_map_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>

#include "mapgen_test_util.h"

namespace covmap::mapgen {
namespace {

using nlohmann::json;
using testing::random_test_sites;
using testing::read_text;
using testing::TempDir;

CoverageMap small_map(OutputFrame frame) {
  const auto sites = random_test_sites(15, 8'000.0, 4.0, 31);
  CoverageMapOptions o;
  o.bin_size_m = 200.0;
  o.max_range_m = 1'500.0;
  o.frame = frame;
  o.centre = io::LonLat{-3.7, 40.4};
  o.errors.gross_fraction = 0.2;
  return generate_coverage_map(std::span<const Site>(sites), o);
}

bool has_temporary(const std::filesystem::path& dir) {
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().filename().string().rfind(".covmap-make-map-tmp", 0) == 0) return true;
  return false;
}

TEST(CoverageMapFiles, WrittenFilesHoldTheMapExactly) {
  for (const OutputFrame frame : {OutputFrame::kPlanar, OutputFrame::kLonLat}) {
    const CoverageMap map = small_map(frame);
    TempDir dir;
    const auto out = dir.path() / "nested" / "out";
    write_coverage_map(map, out);
    EXPECT_FALSE(has_temporary(out));

    const json geo = json::parse(read_text(out / kMapFileName));
    EXPECT_EQ(geo["type"], "FeatureCollection");
    EXPECT_EQ(geo.contains("crs"), frame == OutputFrame::kPlanar) << "GeoJSON without crs means lon/lat";
    ASSERT_EQ(geo["features"].size(), map.features.size());
    for (std::size_t f = 0; f < map.features.size(); ++f) {
      const auto& feature = geo["features"][f];
      const auto& expected = map.features[f];
      EXPECT_EQ(feature["properties"]["sensor"], map.truth[static_cast<std::size_t>(expected.sensor)].id);
      const bool multi = expected.cells.size() > 1;
      EXPECT_EQ(feature["geometry"]["type"], multi ? "MultiPolygon" : "Polygon");
      const json polygons = multi ? feature["geometry"]["coordinates"] : json::array({feature["geometry"]["coordinates"]});
      ASSERT_EQ(polygons.size(), expected.cells.size());
      for (std::size_t c = 0; c < expected.cells.size(); ++c) {
        const auto& rings = expected.cells[c].output;
        ASSERT_EQ(polygons[c].size(), rings.size());
        for (std::size_t k = 0; k < rings.size(); ++k) {
          ASSERT_EQ(polygons[c][k].size(), rings[k].size());
          for (std::size_t v = 0; v < rings[k].size(); ++v) {
            EXPECT_EQ(polygons[c][k][v][0].get<double>(), rings[k][v].x);  // bit-exact round trip
            EXPECT_EQ(polygons[c][k][v][1].get<double>(), rings[k][v].y);
          }
        }
      }
    }

    const json sensors = json::parse(read_text(out / kSensorsFileName));
    ASSERT_EQ(sensors["features"].size(), map.reported.size());
    for (std::size_t k = 0; k < map.reported.size(); ++k) {
      const auto& s = sensors["features"][k];
      EXPECT_EQ(s["geometry"]["type"], "Point");
      EXPECT_EQ(s["geometry"]["coordinates"][0].get<double>(), map.reported[k].output.x);
      EXPECT_EQ(s["properties"]["id"], map.reported[k].id);
      EXPECT_EQ(s["properties"]["tx_power_dbm"].get<double>(), map.reported[k].tx_power_dbm);
      EXPECT_EQ(s["properties"]["weight"].get<double>(), map.reported[k].weight);
      EXPECT_EQ(s["properties"]["position_sigma_m"].get<double>(), map.options.errors.position_sigma_m);
      EXPECT_EQ(s["properties"]["power_sigma_db"].get<double>(), map.options.errors.power_sigma_db);
      EXPECT_FALSE(s["properties"].contains("gross_error")) << "a reported list does not flag its own errors";
    }

    const json truth = json::parse(read_text(out / kTruthFileName));
    EXPECT_EQ(truth["format"], "covmap.mapgen-truth/1");
    EXPECT_EQ(truth["counts"]["covered_bins"].get<std::size_t>(), map.counts.covered_bins);
    EXPECT_EQ(truth["counts"]["gross_errors"].get<std::size_t>(), 3u);  // round(0.2 × 15)
    EXPECT_EQ(truth["raster"]["nx"].get<int>(), map.raster.grid.nx);
    EXPECT_EQ(truth["projection"]["lon0"].get<double>(), -3.7);
    ASSERT_EQ(truth["sensors"].size(), map.truth.size());
    std::size_t gross = 0;
    for (std::size_t k = 0; k < map.truth.size(); ++k) {
      const auto& s = truth["sensors"][k];
      EXPECT_EQ(s["x"].get<double>(), map.truth[k].position.x);
      EXPECT_EQ(s["weight"].get<double>(), map.truth[k].weight);
      EXPECT_EQ(s["reported"]["tx_power_dbm"].get<double>(), map.reported[k].tx_power_dbm);
      if (!s["gross_error"].is_null()) {
        ++gross;
        const std::string kind = s["gross_error"]["kind"];
        EXPECT_EQ(s["gross_error"].contains("position_offset_m"), kind != "power");
        EXPECT_EQ(s["gross_error"].contains("power_offset_db"), kind != "position");
      }
    }
    EXPECT_EQ(gross, 3u);
  }
}

TEST(CoverageMapFiles, TownNamesReachEveryFileAndNamelessSensorsHaveNone) {
  // Lon/lat sensors, every other one named (with a quote and non-ASCII letters to survive JSON).
  std::vector<LonLatSite> sites;
  for (const Site& s : random_test_sites(10, 8'000.0, 4.0, 32)) {
    const std::size_t k = sites.size();
    sites.push_back({.id = s.id, .lon = 7.4 + s.x / 7.6e4, .lat = 46.9 + s.y / 1.1e5, .weight = s.weight,
                     .name = k % 2 ? "" : "Saint-\"Ours\" Ré " + s.id});
  }
  CoverageMapOptions o;
  o.frame = OutputFrame::kLonLat;
  const CoverageMap map = generate_coverage_map(std::span<const LonLatSite>(sites), o);
  TempDir dir;
  write_coverage_map(map, dir.path());
  std::map<std::string, std::string> name_of;
  for (const LonLatSite& s : sites) name_of[s.id] = s.name;
  // A file's entry carries the site's name exactly when the site has one.
  const auto check = [&](const json& entry, const std::string& id) {
    SCOPED_TRACE(id);
    EXPECT_EQ(entry.contains("name"), !name_of.at(id).empty());
    if (entry.contains("name")) {
      EXPECT_EQ(entry["name"], name_of.at(id));
    }
  };
  const json geo = json::parse(read_text(dir.path() / kMapFileName));
  ASSERT_FALSE(geo["features"].empty());
  for (const auto& f : geo["features"]) check(f["properties"], f["properties"]["sensor"]);
  const json sensors = json::parse(read_text(dir.path() / kSensorsFileName));
  ASSERT_EQ(sensors["features"].size(), sites.size());
  for (const auto& f : sensors["features"]) check(f["properties"], f["properties"]["id"]);
  const json truth = json::parse(read_text(dir.path() / kTruthFileName));
  ASSERT_EQ(truth["sensors"].size(), sites.size());
  for (const auto& s : truth["sensors"]) check(s, s["id"]);
}

TEST(CoverageMapFiles, FailureLeavesExistingFilesAndNoTemporary) {
  const CoverageMap map = small_map(OutputFrame::kPlanar);
  TempDir dir;
  std::ofstream(dir.path() / kSensorsFileName) << "old";
  // A non-empty directory where map.geojson should go: its rename fails.
  std::filesystem::create_directories(dir.path() / kMapFileName / "occupied");
  EXPECT_THROW(write_coverage_map(map, dir.path()), std::runtime_error);
  EXPECT_EQ(read_text(dir.path() / kSensorsFileName), "old");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / kTruthFileName));
  EXPECT_FALSE(has_temporary(dir.path()));

  // A file where the directory should be.
  std::ofstream(dir.path() / "plain") << "x";
  EXPECT_THROW(write_coverage_map(map, dir.path() / "plain"), std::runtime_error);
}

}  // namespace
}  // namespace covmap::mapgen
