// RefineOptions::settle: a solve stopped because its sites settled returns the iterate it stopped
// at (the same sites as a solve capped at that many iterations), a rule that never fires leaves
// the solve as it was, and the rule's fields are validated.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "fit_test_data.h"
#include "fitting/refine.h"

namespace covmap::fitting {
namespace {

using testing::make_map;
using testing::noisy;
using testing::perturbed;

struct Problem {
  std::vector<Site> start;
  std::vector<BoundarySample> samples;
};

Problem noisy_problem() {
  const testing::MapData map = make_map(20, 11, 0.5, 2.0, 8);
  std::mt19937_64 rng(3);
  return {perturbed(map.sites, 5, 0.03, 0.2), noisy(map.samples, rng, 1e-3, 1e-3)};
}

RefineOptions quick() {
  RefineOptions o;
  o.compute_covariance = false;
  return o;
}

void expect_same_sites(const RefineResult& a, const RefineResult& b) {
  ASSERT_EQ(a.sites.size(), b.sites.size());
  for (std::size_t i = 0; i < a.sites.size(); ++i) {
    EXPECT_EQ(a.sites[i].x, b.sites[i].x) << "site " << i;
    EXPECT_EQ(a.sites[i].y, b.sites[i].y) << "site " << i;
    EXPECT_EQ(a.sites[i].weight, b.sites[i].weight) << "site " << i;
  }
}

TEST(RefineSettle, StopsAtTheCheckedIterate) {
  const Problem p = noisy_problem();
  // Steps no site can exceed: the sites count as settled at the first check, after 3 successful
  // iterations.
  RefineOptions settled = quick();
  settled.settle = SettleRule{3, 1e9, 1e9, 0.0};
  const RefineResult by_rule = refine_sites(p.start, p.samples, {}, settled);
  EXPECT_EQ(by_rule.summary.termination, Termination::kSettled);
  EXPECT_TRUE(by_rule.summary.converged);
  EXPECT_NE(by_rule.summary.message.find("0 of 20 sites still moving"), std::string::npos) << by_rule.summary.message;

  // summary.iterations counts iteration 0 too: the rule stopped after iteration iterations − 1.
  RefineOptions capped = quick();
  capped.max_iterations = by_rule.summary.iterations - 1;
  ASSERT_GE(capped.max_iterations, 3);
  const RefineResult by_cap = refine_sites(p.start, p.samples, {}, capped);
  ASSERT_EQ(by_cap.summary.termination, Termination::kNoConvergence) << "the problem must need more iterations than that";
  expect_same_sites(by_rule, by_cap);
  EXPECT_EQ(by_rule.summary.iterations, by_cap.summary.iterations);
  EXPECT_EQ(by_rule.summary.final_cost, by_cap.summary.final_cost);
}

TEST(RefineSettle, EverySiteMovingKeepsTheSolveGoing) {
  const Problem p = noisy_problem();
  // From the perturbed start every site moves by more than 1e-12 in the first iteration, so the
  // first check (window 1) cannot stop the solve even with half of the sites allowed to move.
  RefineOptions o = quick();
  o.settle = SettleRule{1, 1e-12, 1e-12, 0.5};
  const RefineResult r = refine_sites(p.start, p.samples, {}, o);
  EXPECT_GT(r.summary.iterations, 1);
}

TEST(RefineSettle, ARuleThatNeverFiresChangesNothing) {
  const Problem p = noisy_problem();
  RefineOptions never = quick();
  never.settle = SettleRule{2, 1e-300, 1e-300, 0.0};
  const RefineResult with_rule = refine_sites(p.start, p.samples, {}, never);
  const RefineResult without = refine_sites(p.start, p.samples, {}, quick());
  EXPECT_EQ(without.summary.termination, Termination::kConvergence);
  EXPECT_EQ(with_rule.summary.termination, without.summary.termination);
  EXPECT_EQ(with_rule.summary.iterations, without.summary.iterations);
  expect_same_sites(with_rule, without);
}

TEST(RefineSettle, FieldsAreValidated) {
  std::string error;
  RefineOptions o;
  o.settle = SettleRule{0, 1.0, 1.0, 0.0};
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("settle.window"), std::string::npos) << error;
  o.settle = SettleRule{5, 0.0, 1.0, 0.0};
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("settle.position_step"), std::string::npos) << error;
  o.settle = SettleRule{5, 1.0, NAN, 0.0};
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("settle.log_weight_step"), std::string::npos) << error;
  o.settle = SettleRule{5, 1.0, 1.0, 1.0};
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("settle.moving_share"), std::string::npos) << error;
  o.settle = SettleRule{5, 1.0, 1.0, 0.01};
  EXPECT_TRUE(o.IsValid(&error)) << error;
}

}  // namespace
}  // namespace covmap::fitting
