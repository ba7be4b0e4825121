// One residual block per pair of sites (fitting/boundary_group_cost.h) must pose the same problem
// to Ceres as one block per sample under the same loss. The oracle is Ceres itself: the per-sample
// problem built from ceres::AutoDiffCostFunction<BoundaryResidual> and the loss, whose corrections
// Ceres applies; the pair problem (build_problem under a loss) must give the same cost, gradient
// and Gauss–Newton matrix JᵀJ (row order differs, so the Jacobians are compared through JᵀJ).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <ceres/crs_matrix.h>
#include <ceres/loss_function.h>
#include <ceres/problem.h>

#include "fitting/boundary_group_cost.h"
#include "fitting/problem_setup.h"
#include "fitting/residuals.h"
#include "fitting/robust_loss.h"

namespace covmap::fitting::detail {
namespace {

struct Evaluated {
  double cost = 0.0;
  std::vector<double> gradient;
  std::vector<double> normal;  // JᵀJ, dense, row-major
};

Evaluated evaluate(ceres::Problem& problem, std::size_t columns) {
  Evaluated e;
  ceres::CRSMatrix jacobian;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), &e.cost, nullptr, &e.gradient, &jacobian);
  e.normal.assign(columns * columns, 0.0);
  for (int row = 0; row < jacobian.num_rows; ++row)
    for (int p = jacobian.rows[row]; p < jacobian.rows[row + 1]; ++p)
      for (int q = jacobian.rows[row]; q < jacobian.rows[row + 1]; ++q)
        e.normal[jacobian.cols[p] * columns + jacobian.cols[q]] += jacobian.values[p] * jacobian.values[q];
  return e;
}

// Sites on a small grid with varied weights; samples scattered about each pair's midpoint, some
// far off (outliers, where the loss bends), in an order that interleaves the pairs.
struct Scene {
  std::vector<Site> sites;
  std::vector<BoundarySample> samples;
};

Scene scene() {
  Scene s;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-40.0, 40.0), offset(-300.0, 300.0);
  for (int i = 0; i < 6; ++i)
    s.sites.push_back({std::to_string(i), 1000.0 * (i % 3) + jitter(rng), 1000.0 * (i / 3) + jitter(rng), 1.0 + 0.3 * i});
  const std::pair<int, int> pairs[] = {{0, 1}, {1, 2}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {4, 1}};
  for (int k = 0; k < 12; ++k)
    for (auto [a, b] : pairs) {
      const Site &sa = s.sites[a], &sb = s.sites[b];
      const double spread = k % 5 == 0 ? 6.0 : 1.0;  // every fifth sample an outlier
      s.samples.push_back({{0.5 * (sa.x + sb.x) + spread * offset(rng), 0.5 * (sa.y + sb.y) + spread * offset(rng)}, a, b, 29.0, 0});
    }
  return s;
}

void expect_same_problem(const ceres::LossFunction* loss) {
  const Scene s = scene();
  const std::size_t columns = kSiteBlockSize * s.sites.size();
  // The per-sample problem, over its own copy of the parameters.
  std::vector<SiteBlock> per_sample = initial_blocks(s.sites);
  ceres::Problem::Options options;
  options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem reference(options);
  for (SiteBlock& block : per_sample) reference.AddParameterBlock(block.data(), kSiteBlockSize);
  for (const BoundarySample& sample : s.samples)
    reference.AddResidualBlock(BoundaryResidual::Create(sample.p.x, sample.p.y, 1.0 / sample.sigma),
                               const_cast<ceres::LossFunction*>(loss), per_sample[sample.site_a].data(),
                               per_sample[sample.site_b].data());
  // The pair problem as refine_sites builds it (weight priors on every site, so no gauge block).
  std::vector<SiteBlock> paired = initial_blocks(s.sites);
  std::vector<SitePrior> priors;
  for (std::size_t i = 0; i < s.sites.size(); ++i) priors.push_back({static_cast<int>(i), {0, 0}, 0.0, std::log(s.sites[i].weight), 1.0});
  const Layout layout = make_layout(s.sites, s.samples, priors);
  double log_range = 0.0;
  BuiltProblem built = build_problem(paired, &log_range, layout, s.samples, {}, const_cast<ceres::LossFunction*>(loss));
  ASSERT_LT(built.problem->NumResidualBlocks(), static_cast<int>(s.samples.size()));  // grouped

  const Evaluated want = evaluate(reference, columns);
  const Evaluated got = evaluate(*built.problem, columns);
  EXPECT_NEAR(got.cost, want.cost, 1e-12 * want.cost);
  ASSERT_EQ(got.gradient.size(), want.gradient.size());
  double gradient_scale = 0.0, normal_scale = 0.0;
  for (double g : want.gradient) gradient_scale = std::max(gradient_scale, std::abs(g));
  for (double v : want.normal) normal_scale = std::max(normal_scale, std::abs(v));
  for (std::size_t i = 0; i < want.gradient.size(); ++i) EXPECT_NEAR(got.gradient[i], want.gradient[i], 1e-12 * gradient_scale);
  for (std::size_t i = 0; i < want.normal.size(); ++i) EXPECT_NEAR(got.normal[i], want.normal[i], 1e-12 * normal_scale);
}

TEST(PairBlocks, PoseTheSameProblemAsOneBlockPerSampleUnderCauchy) {
  const auto loss = make_loss(RobustLoss::kCauchy, 3.0);
  expect_same_problem(loss.get());
}

TEST(PairBlocks, PoseTheSameProblemUnderHuber) {
  const auto loss = make_loss(RobustLoss::kHuber, 1.0);
  expect_same_problem(loss.get());
}

// A loss that curves upward (ρ″ > 0) takes Ceres' curvature correction, not only the √ρ′ scaling.
TEST(PairBlocks, PoseTheSameProblemUnderALossWithPositiveCurvature) {
  const ceres::TolerantLoss loss(2.0, 1.0);
  expect_same_problem(&loss);
}

// The samples between sites a and b, as a PairCost takes them.
std::vector<PairSample> pair_samples(const Scene& s, int a, int b) {
  std::vector<PairSample> pair;
  for (const BoundarySample& sample : s.samples)
    if (sample.site_a == a && sample.site_b == b) pair.push_back({sample.p.x, sample.p.y, 1.0 / sample.sigma});
  return pair;
}

// Ceres' inner iterations hold every site but one, so they ask a pair block for one side's
// Jacobian only, which PairCost evaluates with half the derivative slots. Those rows must be the
// full evaluation's, bit for bit (the inner iterations and the outer steps see one problem), and
// so must the residuals. (Without any Jacobian the residuals come from plain doubles, as in
// ceres::AutoDiffCostFunction, and may differ in the last bit.)
TEST(PairBlocks, OneSidedJacobiansAreTheFullOnesBitForBit) {
  const Scene s = scene();
  const auto loss = make_loss(RobustLoss::kCauchy, 3.0);
  const std::vector<PairSample> pair = pair_samples(s, 0, 1);
  ASSERT_GE(pair.size(), 10u);
  const PairCost cost(pair, loss.get());
  const std::vector<SiteBlock> blocks = initial_blocks(s.sites);
  const double* parameters[] = {blocks[0].data(), blocks[1].data()};
  const std::size_t rows = pair.size(), entries = rows * kSiteBlockSize;
  std::vector<double> r_full(rows), ja_full(entries), jb_full(entries);
  double* both[] = {ja_full.data(), jb_full.data()};
  ASSERT_TRUE(cost.Evaluate(parameters, r_full.data(), both));
  const double rho_full = cost.last_rho();
  std::vector<double> r_a(rows), ja(entries, -1.0), r_b(rows), jb(entries, -1.0);
  double* only_a[] = {ja.data(), nullptr};
  double* only_b[] = {nullptr, jb.data()};
  ASSERT_TRUE(cost.Evaluate(parameters, r_a.data(), only_a));
  EXPECT_EQ(cost.last_rho(), rho_full);
  ASSERT_TRUE(cost.Evaluate(parameters, r_b.data(), only_b));
  EXPECT_EQ(cost.last_rho(), rho_full);
  for (std::size_t i = 0; i < rows; ++i) {
    EXPECT_EQ(r_a[i], r_full[i]) << "sample " << i;
    EXPECT_EQ(r_b[i], r_full[i]) << "sample " << i;
  }
  for (std::size_t k = 0; k < entries; ++k) {
    EXPECT_EQ(ja[k], ja_full[k]) << "entry " << k;
    EXPECT_EQ(jb[k], jb_full[k]) << "entry " << k;
  }
  // And the sides are not trivially equal: each carries its own derivatives.
  EXPECT_NE(ja_full, jb_full);
}

// A PairCost copies its last evaluation when asked for the same point again (boundary_group_cost.h).
// The oracle is a fresh PairCost, which has nothing to copy: at a point seen before, at a point one
// micrometre away and back at the first, each answer must be the fresh one's, bit for bit.
TEST(PairBlocks, AnEvaluationAgainAtTheSamePointIsAFreshOne) {
  const Scene s = scene();
  const auto loss = make_loss(RobustLoss::kCauchy, 3.0);
  const std::vector<PairSample> pair = pair_samples(s, 1, 4);
  ASSERT_GE(pair.size(), 10u);
  const std::vector<SiteBlock> blocks = initial_blocks(s.sites);
  SiteBlock moved = blocks[4];
  moved[0] += 1e-6;  // a micrometre: every residual changes
  struct Answer {
    std::vector<double> residuals, ja, jb;
    double rho = 0.0;
    bool operator==(const Answer&) const = default;
  };
  const std::size_t rows = pair.size();
  auto evaluate_pair = [rows](const PairCost& cost, const SiteBlock& a, const SiteBlock& b) {
    Answer out{std::vector<double>(rows), std::vector<double>(rows * kSiteBlockSize), std::vector<double>(rows * kSiteBlockSize)};
    const double* parameters[] = {a.data(), b.data()};
    double* jacobians[] = {out.ja.data(), out.jb.data()};
    EXPECT_TRUE(cost.Evaluate(parameters, out.residuals.data(), jacobians));
    out.rho = cost.last_rho();
    return out;
  };
  const PairCost kept(pair, loss.get());
  const SiteBlock* sequence[] = {&blocks[4], &blocks[4], &moved, &moved, &blocks[4]};
  for (const SiteBlock* b : sequence) {
    const PairCost fresh(pair, loss.get());
    EXPECT_TRUE(evaluate_pair(kept, blocks[1], *b) == evaluate_pair(fresh, blocks[1], *b));
  }
  EXPECT_FALSE(evaluate_pair(kept, blocks[1], moved) == evaluate_pair(kept, blocks[1], blocks[4]));
}

}  // namespace
}  // namespace covmap::fitting::detail
