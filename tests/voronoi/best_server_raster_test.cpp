#include "voronoi/best_server_raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace covmap::voronoi {
namespace {

// The oracle: every site, plain arithmetic.
int brute_force_owner(const std::vector<Site>& sites, double px, double py, double max_range = -1.0) {
  int best = kNone;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const double dx = px - sites[k].x, dy = py - sites[k].y;
    const double d = std::sqrt(dx * dx + dy * dy) / sites[k].weight;
    if (d < best_d) best_d = d, best = static_cast<int>(k);
  }
  if (max_range >= 0.0 && best_d > max_range) return kNone;
  return best;
}

// Sites uniform in a size × size square, weights log-uniform in [1/ratio, 1].
std::vector<Site> random_test_sites(int n, double size, double ratio, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Site> sites;
  for (int k = 0; k < n; ++k)
    sites.push_back(Site{"s" + std::to_string(k), size * unit(rng), size * unit(rng), std::exp(-std::log(ratio) * unit(rng))});
  return sites;
}

// Every bin against brute force over all sites, bit for bit.
void expect_brute_force(const std::vector<Site>& sites, const RasterGrid& grid, std::optional<double> range) {
  const BestServerRaster raster = best_server_raster(sites, grid, range);
  ASSERT_EQ(raster.labels.size(), grid.bins());
  int mismatches = 0;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      const double px = grid.x0 + (i + 0.5) * grid.bin, py = grid.y0 + (j + 0.5) * grid.bin;
      const int expected = brute_force_owner(sites, px, py, range ? *range : -1.0);
      if (raster.labels[grid.index(i, j)] != expected && ++mismatches <= 5)
        ADD_FAILURE() << "bin (" << i << ", " << j << "): got " << raster.labels[grid.index(i, j)] << ", brute force "
                      << expected;
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(BestServerRaster, MatchesBruteForceOnRandomWeightedSites) {
  for (const double ratio : {1.0, 3.0, 30.0}) {
    SCOPED_TRACE(ratio);
    const auto sites = random_test_sites(300, 10'000.0, ratio, 7);
    expect_brute_force(sites, RasterGrid{-1000.0, -1000.0, 50.0, 240, 240}, std::nullopt);
  }
}

TEST(BestServerRaster, MatchesBruteForceWithMaximumRange) {
  const auto sites = random_test_sites(80, 10'000.0, 10.0, 11);
  for (const double range : {300.0, 800.0, 2000.0}) {
    SCOPED_TRACE(range);
    expect_brute_force(sites, RasterGrid{0.0, 0.0, 50.0, 200, 200}, range);
  }
}

TEST(BestServerRaster, TiesGoToTheLowestIndex) {
  // Equal weights on an integer lattice: many bin centres are exactly equidistant from two or four
  // sites. Swapping the site order must swap the winners on those bins.
  std::vector<Site> sites;
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 5; ++b) sites.push_back(Site{"g" + std::to_string(a * 5 + b), 4.0 * a, 4.0 * b, 1.0});
  std::vector<Site> reversed(sites.rbegin(), sites.rend());
  const RasterGrid grid{-0.5, -0.5, 1.0, 17, 17};  // bin centres at the integers 0..16
  expect_brute_force(sites, grid, std::nullopt);
  expect_brute_force(reversed, grid, std::nullopt);
  const auto forward = best_server_raster(sites, grid);
  const auto backward = best_server_raster(reversed, grid);
  const std::size_t tie = grid.index(2, 0);  // centre (2, 0): distance 2 from g0 (0,0) and g5 (4,0)
  EXPECT_EQ(sites[static_cast<std::size_t>(forward.labels[tie])].id, "g0");
  EXPECT_EQ(reversed[static_cast<std::size_t>(backward.labels[tie])].id, "g5");
}

TEST(BestServerRaster, DominatedSiteOwnsNothing) {
  // A weak site next to a strong one: its Apollonius disc is smaller than a bin here.
  const std::vector<Site> sites = {{"strong", 0.0, 0.0, 1.0}, {"weak", 10.0, 0.0, 0.01}};
  const RasterGrid grid{-500.0, -500.0, 100.0, 10, 10};
  expect_brute_force(sites, grid, std::nullopt);
  const auto raster = best_server_raster(sites, grid);
  for (const int label : raster.labels) EXPECT_EQ(label, 0);
}

TEST(BestServerRaster, RangeZeroLeavesEverythingUncovered) {
  const auto sites = random_test_sites(20, 1000.0, 2.0, 3);
  const auto raster = best_server_raster(sites, RasterGrid{0.0, 0.0, 10.0, 50, 50}, 0.0);
  for (const int label : raster.labels) EXPECT_EQ(label, kNone);
}

TEST(BestServerRaster, RejectsEmptyGrids) {
  const auto sites = random_test_sites(3, 10.0, 1.0, 1);
  EXPECT_THROW(best_server_raster(sites, RasterGrid{0, 0, 1.0, 0, 5}), std::invalid_argument);
  EXPECT_THROW(best_server_raster(sites, RasterGrid{0, 0, 0.0, 5, 5}), std::invalid_argument);
  EXPECT_THROW(best_server_raster(sites, RasterGrid{0, 0, 1.0, 5, 5}, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace covmap::voronoi
