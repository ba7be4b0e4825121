// The refinement's result must be the same, bit for bit, whatever RefineOptions::threads, run
// after run: Ceres adds its threads' partial costs and gradients in an order that depends on
// scheduling, so the solve itself must not use them (fitting/refine.cpp).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "fit_test_data.h"
#include "fitting/refine.h"

namespace covmap::fitting {
namespace {

using testing::boundary_samples;
using testing::noisy;
using testing::perturbed;

// Every number of the result that the audit reads: sites, uncertainties, residuals, cost.
void expect_identical(const RefineResult& a, const RefineResult& b, int threads) {
  SCOPED_TRACE("threads " + std::to_string(threads));
  EXPECT_EQ(a.summary.iterations, b.summary.iterations);
  EXPECT_EQ(a.summary.final_cost, b.summary.final_cost);
  ASSERT_EQ(a.sites.size(), b.sites.size());
  for (std::size_t i = 0; i < a.sites.size(); ++i) {
    EXPECT_EQ(a.sites[i].x, b.sites[i].x) << "site " << i;
    EXPECT_EQ(a.sites[i].y, b.sites[i].y) << "site " << i;
    EXPECT_EQ(a.sites[i].weight, b.sites[i].weight) << "site " << i;
    EXPECT_EQ(a.uncertainty[i].sigma_x, b.uncertainty[i].sigma_x) << "site " << i;
    EXPECT_EQ(a.uncertainty[i].cov_xy, b.uncertainty[i].cov_xy) << "site " << i;
    EXPECT_EQ(a.uncertainty[i].sigma_log_weight, b.uncertainty[i].sigma_log_weight) << "site " << i;
  }
  EXPECT_EQ(a.sample_residual, b.sample_residual);
}

TEST(RefineThreads, ResultDoesNotDependOnThreadCount) {
  // Noisy samples, so that the optimum has a non-zero cost whose sums depend on their order.
  // 40 sites (0.1 apart in the unit square), 40 samples per arc: thousands of residual blocks.
  const auto sites = testing::random_sites(40, 5, 1.0, 3.0, 0.1);
  std::mt19937_64 rng(9);
  const auto samples = noisy(boundary_samples(sites, 40), rng, 1e-3, 1e-3);
  ASSERT_GT(samples.size(), 2000u);
  const auto start = perturbed(sites, 6, 0.01, 0.1);
  RefineOptions options;
  options.threads = 1;
  const RefineResult one = refine_sites(start, samples, {}, options);
  ASSERT_TRUE(one.summary.converged) << one.summary.message;
  for (int threads : {2, 4, 4, 8}) {
    options.threads = threads;
    expect_identical(one, refine_sites(start, samples, {}, options), threads);
  }
}

}  // namespace
}  // namespace covmap::fitting
