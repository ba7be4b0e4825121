// Clustered layouts cut from the committed town lists: the windows are real towns (positions are the
// projected towns), compact, deterministic per seed and different across seeds; weights from
// population or power classes; lon/lat maps through the command with every model.
#include "tools/mapgen/town_layouts.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "tools/mapgen/coverage_map_files.h"
#include "tools/mapgen/coverage_map_generator.h"
#include "tools/mapgen/lonlat_sites_csv.h"
#include "io/coverage_map.h"
#include "io/local_projection.h"
#include "make_map_run.h"
#include "mapgen_test_util.h"

namespace covmap::mapgen {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::read_text;
using testing::TempDir;

const fs::path kTowns = fs::path(COVMAP_SOURCE_DIR) / "datasets" / "towns";

std::vector<LonLatSite> towns(const char* name) { return read_lonlat_sites_csv(kTowns / name).sites; }

// Squared distance on the local equirectangular plane about c, in degrees (the documented ranking).
double near2(const LonLatSite& a, const LonLatSite& c) {
  const double dx = (a.lon - c.lon) * std::cos(c.lat * M_PI / 180.0), dy = a.lat - c.lat;
  return dx * dx + dy * dy;
}

TEST(TownLists, AreSmallAttributedAndReadable) {
  std::uintmax_t bytes = 0;
  int lists = 0;
  for (const auto& entry : fs::directory_iterator(kTowns)) {
    if (entry.path().extension() != ".csv") continue;
    ++lists;
    bytes += fs::file_size(entry.path());
    const auto table = read_lonlat_sites_csv(entry.path());
    EXPECT_GE(table.sites.size(), 150u) << entry.path();
    EXPECT_NE(read_text(entry.path()).find("GeoNames (geonames.org), CC BY 4.0"), std::string::npos) << entry.path();
  }
  EXPECT_GE(lists, 4);
  EXPECT_LE(bytes, 150'000u);
}

TEST(TownLayouts, WindowIsTheNearestTownsOfTheList) {
  const auto list = towns("nordrhein_westfalen.csv");
  TownLayoutOptions o;
  o.count = 80;
  o.seed = 4;
  const TownWindow w = clustered_town_sites(list, o);
  ASSERT_EQ(w.sites.size(), 80u);
  const LonLatSite& centre = list[w.centre];
  std::map<std::string, const LonLatSite*> by_id;
  for (const auto& t : list) by_id[t.id] = &t;
  double farthest_in = 0.0;
  std::set<std::string> chosen;
  for (const auto& s : w.sites) {
    ASSERT_TRUE(by_id.count(s.id)) << s.id;
    const LonLatSite& t = *by_id[s.id];
    EXPECT_EQ(s.lon, t.lon);
    EXPECT_EQ(s.lat, t.lat);
    EXPECT_EQ(s.weight, t.weight);  // population weights: the list's column
    farthest_in = std::max(farthest_in, near2(t, centre));
    chosen.insert(s.id);
  }
  EXPECT_TRUE(chosen.count(centre.id));
  for (const auto& t : list)
    if (!chosen.count(t.id)) {
      EXPECT_GE(near2(t, centre), farthest_in) << t.id << " is nearer than a chosen town";
    }
}

TEST(TownLayouts, DeterministicPerSeedAndDifferentAcrossSeeds) {
  const auto list = towns("scotland.csv");
  TownLayoutOptions o;
  o.count = 50;
  std::set<std::vector<std::string>> windows;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    o.seed = seed;
    const TownWindow a = clustered_town_sites(list, o), b = clustered_town_sites(list, o);
    std::vector<std::string> ids_a, ids_b;
    for (const auto& s : a.sites) ids_a.push_back(s.id);
    for (const auto& s : b.sites) ids_b.push_back(s.id);
    EXPECT_EQ(ids_a, ids_b);
    windows.insert(ids_a);
  }
  EXPECT_GE(windows.size(), 4u);
}

TEST(TownLayouts, PowerClassesGoToTheMostIsolatedTownsFirst) {
  const auto list = towns("iowa.csv");
  TownLayoutOptions o;
  o.count = 60;
  o.seed = 2;
  o.weights = TownWeights::kPowerClasses;
  o.power_classes_dbm = {31.0, 43.0, 37.0};  // any order
  const TownWindow w = clustered_town_sites(list, o);
  std::map<double, int> per_class;
  std::vector<std::pair<double, double>> spacing_weight;
  // Local spacing on the documented plane: about the window's centre town.
  const LonLatSite& centre = list[w.centre];
  const auto plane2 = [&](const LonLatSite& a, const LonLatSite& b) {
    const double c = std::cos(centre.lat * M_PI / 180.0);
    return ((a.lon - b.lon) * c) * ((a.lon - b.lon) * c) + (a.lat - b.lat) * (a.lat - b.lat);
  };
  for (const auto& a : w.sites) {
    double nearest = INFINITY;
    for (const auto& b : w.sites)
      if (&a != &b) nearest = std::min(nearest, plane2(b, a));
    spacing_weight.emplace_back(nearest, a.weight);
    ++per_class[a.weight];
  }
  ASSERT_EQ(per_class.size(), 3u);
  for (const double p : {43.0, 37.0, 31.0}) {
    const double weight = std::pow(10.0, (p - 43.0) / 35.0);
    const auto it = std::find_if(per_class.begin(), per_class.end(), [&](auto& c) { return std::abs(c.first - weight) < 1e-12; });
    ASSERT_NE(it, per_class.end()) << p << " dBm";
    EXPECT_EQ(it->second, 20);
  }
  // A higher class never sits in a denser place than a lower one (ties in spacing aside).
  for (const auto& [sa, wa] : spacing_weight)
    for (const auto& [sb, wb] : spacing_weight)
      if (wa > wb) {
        EXPECT_GE(sa, sb * (1.0 - 1e-12));
      }
}

TEST(TownLayouts, RejectsImpossibleWindows) {
  const auto list = towns("iowa.csv");
  TownLayoutOptions o;
  o.count = static_cast<int>(list.size()) + 1;
  EXPECT_THROW(clustered_town_sites(list, o), std::invalid_argument);
  o.count = 1;
  EXPECT_THROW(clustered_town_sites(list, o), std::invalid_argument);
  o.count = 10;
  o.weights = TownWeights::kPowerClasses;
  o.power_classes_dbm.clear();
  EXPECT_THROW(clustered_town_sites(list, o), std::invalid_argument);
}

// Pruning on a clustered layout (cells from a few hundred metres to kilometres wide, one bin size):
// every model's labels equal the brute-force argmax of received power at sampled bins, with and
// without a reception limit.
TEST(TownLayouts, ClusteredWindowsAreLabelledAsBruteForceUnderEveryModel) {
  TownLayoutOptions t;
  t.count = 80;
  t.seed = 3;
  const TownWindow window = clustered_town_sites(towns("netherlands.csv"), t);
  for (const PropagationModel model : kAllPropagationModels) {
    if (model == PropagationModel::kMultiplicative) continue;  // voronoi's raster, tested there
    for (const std::optional<double> range : {std::optional<double>{}, std::optional<double>{5000.0}}) {
      CoverageMapOptions o;
      o.propagation.model = model;
      o.max_range_m = range;
      o.seed = 4;
      const CoverageMap map = generate_coverage_map(std::span<const LonLatSite>(window.sites), o);
      const RasterGrid& g = map.raster.grid;
      for (std::size_t b = 0; b < g.bins(); b += 53) {
        const Point p{g.center_x(static_cast<int>(b % static_cast<std::size_t>(g.nx))),
                      g.center_y(static_cast<int>(b / static_cast<std::size_t>(g.nx)))};
        int best = kNone;
        double best_power = -INFINITY;
        for (std::size_t k = 0; k < map.truth.size(); ++k) {
          const double power = received_power_dbm(map.propagation, k, p);
          if (power > best_power) best_power = power, best = static_cast<int>(k);
        }
        if (range && best_power < *map.sensitivity_dbm) best = kNone;
        ASSERT_EQ(map.raster.labels[b], best) << to_string(model) << " bin " << b;
      }
    }
  }
}

// The command end to end, for each model, in lon/lat with a reception limit: the true positions are
// the towns projected about the map's centre, truth.json records layout and model, and the map
// reads back as a valid lon/lat coverage map with one cell per polygon.
TEST(TownLayouts, CommandMakesLonLatMapsOfTownWindowsUnderEveryModel) {
  const auto list = towns("ile_de_france.csv");
  std::map<std::string, const LonLatSite*> by_id;
  for (const auto& t : list) by_id[t.id] = &t;
  for (const PropagationModel model : kAllPropagationModels) {
    TempDir dir;
    ASSERT_EQ(testing::run_make_map_args({"--towns", (kTowns / "ile_de_france.csv").string(), "--count", "40", "--model",
                           std::string(to_string(model)), "--max-range", "2000", "--seed", "9", "-o", dir.path().string()}),
              0);
    const json truth = json::parse(read_text(dir.path() / kTruthFileName));
    EXPECT_EQ(truth["generator"]["frame"], "lonlat");
    EXPECT_EQ(truth["layout"]["weights"], "population");
    EXPECT_EQ(truth["layout"]["towns_in_file"].get<std::size_t>(), list.size());
    EXPECT_EQ(truth.contains("model") || truth["generator"].contains("model"), model != PropagationModel::kMultiplicative);
    const auto projection = io::LocalProjection::about(truth["projection"]["lon0"].get<double>(),
                                                       truth["projection"]["lat0"].get<double>());
    ASSERT_EQ(truth["sensors"].size(), 40u);
    for (const auto& s : truth["sensors"]) {
      const LonLatSite& t = *by_id.at(s["id"].get<std::string>());
      EXPECT_EQ(s["lon"].get<double>(), t.lon);
      EXPECT_EQ(s["lat"].get<double>(), t.lat);
      const Point p = projection.forward(t.lon, t.lat);
      EXPECT_EQ(s["x"].get<double>(), p.x);
      EXPECT_EQ(s["y"].get<double>(), p.y);
    }
    EXPECT_LT(truth["counts"]["covered_bins"].get<std::size_t>(), truth["counts"]["bins"].get<std::size_t>());
    const io::CoverageMap read = io::read_coverage_map(dir.path() / kMapFileName);
    EXPECT_EQ(read.cells.size(), 40u - truth["counts"]["sensors_without_bins"].get<std::size_t>()) << to_string(model);
  }
}

}  // namespace
}  // namespace covmap::mapgen
