// Exact boundary samples from the engine's diagram: refinement from a perturbed start must return
// the true sites and weight ratios.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fit_test_data.h"
#include "fitting/refine.h"

namespace covmap::fitting {
namespace {

using testing::make_map;
using testing::perturbed;

// Largest position error and largest relative error of the weight ratios (weights normalised to a
// largest of 1 on both sides).
struct Errors {
  double position = 0.0;
  double weight = 0.0;
};

Errors compare(const std::vector<Site>& fitted, const std::vector<Site>& truth) {
  double max_true = 0.0;
  for (const auto& s : truth) max_true = std::max(max_true, s.weight);
  Errors e;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    e.position = std::max(e.position, std::hypot(fitted[i].x - truth[i].x, fitted[i].y - truth[i].y));
    e.weight = std::max(e.weight, std::abs(fitted[i].weight / (truth[i].weight / max_true) - 1.0));
  }
  return e;
}

class ExactRecovery : public ::testing::TestWithParam<int> {};

TEST_P(ExactRecovery, WeightedSites) {
  const int seed = GetParam();
  const auto map = make_map(7, seed, 1.0, 2.0, 8);
  ASSERT_GT(map.samples.size(), 50u);
  const auto start = perturbed(map.sites, 100 + seed, 0.02, 0.05);
  ASSERT_GT(compare(start, map.sites).position, 1e-3);
  for (RobustLoss loss : {RobustLoss::kCauchy, RobustLoss::kNone}) {
    RefineOptions options;
    options.loss = loss;
    const RefineResult result = refine_sites(start, map.samples, {}, options);
    EXPECT_TRUE(result.summary.converged) << result.summary.brief() << " " << result.summary.message;
    const Errors e = compare(result.sites, map.sites);
    // Sites span the unit square: absolute is relative here.
    EXPECT_LT(e.position, 1e-6) << "seed " << seed << " " << to_string(loss);
    EXPECT_LT(e.weight, 1e-6) << "seed " << seed << " " << to_string(loss);
    EXPECT_LT(result.summary.rms_residual, 1e-12);
    double largest = 0.0;
    for (const auto& s : result.sites) largest = std::max(largest, s.weight);
    EXPECT_EQ(largest, 1.0);
    for (std::size_t i = 0; i < map.sites.size(); ++i) {
      EXPECT_EQ(result.sites[i].id, map.sites[i].id);
      EXPECT_EQ(result.status[i], SiteStatus::kRefined);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, ExactRecovery, ::testing::Values(1, 2, 3, 4));

TEST(ExactRecovery, EqualWeightsGiveLinesAndAreRecovered) {
  const auto map = make_map(7, 11, 1.5, 1.5, 8);
  // A perturbed start has unequal weights: every bisector starts as a circle.
  const auto start = perturbed(map.sites, 12, 0.02, 0.05);
  RefineOptions options;
  options.threads = 2;
  const RefineResult result = refine_sites(start, map.samples, {}, options);
  EXPECT_TRUE(result.summary.converged) << result.summary.message;
  const Errors e = compare(result.sites, map.sites);
  EXPECT_LT(e.position, 1e-6);
  EXPECT_LT(e.weight, 1e-6);
}

TEST(ExactRecovery, ProjectedCoordinatesInMetres) {
  // A map 1 km across, 500 km from the origin (projected coordinates): the same relative accuracy.
  const auto map = make_map(7, 2, 1.0, 2.0, 8);
  const auto to_metres = [](double v) { return 5e5 + 1000.0 * v; };
  std::vector<Site> truth = map.sites;
  for (auto& s : truth) {
    s.x = to_metres(s.x);
    s.y = to_metres(s.y);
  }
  std::vector<BoundarySample> samples = map.samples;
  for (auto& s : samples) {
    s.p = {to_metres(s.p.x), to_metres(s.p.y)};
    s.sigma = 1.0;  // a metre, nominal
  }
  const RefineResult result = refine_sites(perturbed(truth, 3, 20.0, 0.05), samples);
  EXPECT_TRUE(result.summary.converged) << result.summary.message;
  const Errors e = compare(result.sites, truth);
  EXPECT_LT(e.position, 1e-6 * 1000.0);
  EXPECT_LT(e.weight, 1e-6);
}

}  // namespace
}  // namespace covmap::fitting

namespace covmap::fitting {
namespace {

// The heartbeat sees every iteration the solver reports, numbered from 0, and changes nothing.
TEST(RefineHeartbeat, CalledOncePerIterationInOrder) {
  const auto map = make_map(7, 3, 1.0, 2.0, 8);
  const auto start = perturbed(map.sites, 103, 0.02, 0.05);
  RefineOptions options;
  std::vector<int> seen;
  options.on_iteration = [&](int iteration) { seen.push_back(iteration); };
  const RefineResult with = refine_sites(start, map.samples, {}, options);
  options.on_iteration = nullptr;
  const RefineResult without = refine_sites(start, map.samples, {}, options);
  ASSERT_FALSE(seen.empty());
  for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k], static_cast<int>(k));
  // Ceres reports iteration 0 (the start) and then steps; the step that ends the solve may come
  // without a callback.
  EXPECT_GE(static_cast<int>(seen.size()), with.summary.iterations);
  EXPECT_LE(static_cast<int>(seen.size()), with.summary.iterations + 1);
  for (std::size_t i = 0; i < with.sites.size(); ++i) EXPECT_EQ(with.sites[i].x, without.sites[i].x);
}

}  // namespace
}  // namespace covmap::fitting
