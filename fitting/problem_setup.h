// The least-squares problem of refine_sites: parameter blocks, groups and their gauge, residuals.
//
// One Ceres problem is built to solve (robust loss, samples at 1/σ) and another, over the same
// parameter memory, for the covariance (no loss, samples at √c_i/σ with c_i the IRLS weight over the
// noise variance factor, fitting/robust_loss.h). Both share this construction so the two cannot
// disagree about blocks, priors or gauge.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include <ceres/problem.h>

#include "fitting/refine.h"
#include "fitting/residuals.h"

namespace covmap::fitting::detail {

using SiteBlock = std::array<double, kSiteBlockSize>;  // x, y, u = log(weight)

// Which sites the samples tie together, and how each group's weight scale is fixed.
struct Layout {
  std::vector<int> sample_count;     // per site
  std::vector<int> group;            // per site: its connected group, kNone for a site without samples
  std::vector<int> group_reference;  // per group: the site whose u is held, kNone if weight priors fix the scale
  bool range = false;                // some sample is a range edge: ρ = log R is a parameter
  bool hold_range = false;           // ... held at its initial value (RefineOptions::held_range)
  std::size_t free_parameters = 0;   // tangent dimension of the problem
};

Layout make_layout(std::span<const Site> initial, std::span<const BoundarySample> samples,
                   std::span<const SitePrior> priors);

std::vector<SiteBlock> initial_blocks(std::span<const Site> initial);

struct BuiltProblem {
  std::vector<std::unique_ptr<ceres::LossFunction>> pair_losses;  // of the pair blocks; outlive the problem
  std::unique_ptr<ceres::Problem> problem;
  std::vector<ceres::ResidualBlockId> sample_blocks;  // per sample, in order: the block holding it
};

// Blocks of the sites with samples (and `log_range`, ρ = log R, when layout.range), one residual
// per sample (its 1/σ times sample_factor[i], or times 1 when sample_factor is empty) under `loss`
// (not owned; may be nullptr; with a loss, the boundary samples of each pair of sites share one
// block, each still under its own loss: boundary_group_cost.h), their priors, and the gauge (a SubsetManifold holding u of each
// group_reference). `blocks` and `log_range` must outlive the problem.
BuiltProblem build_problem(std::vector<SiteBlock>& blocks, double* log_range, const Layout& layout,
                           std::span<const BoundarySample> samples, std::span<const SitePrior> priors,
                           ceres::LossFunction* loss, std::span<const double> sample_factor = {});

// Signed first-order distance of sample p from the bisector of its sites at `blocks`, or from the
// range circle of its site for a range edge (units of p).
double geometric_residual(const std::vector<SiteBlock>& blocks, double log_range, const BoundarySample& sample);

// A start for ρ = log R: the median over the range samples of log |p − a| − u_a (0 without any).
double initial_log_range(const std::vector<SiteBlock>& blocks, std::span<const BoundarySample> samples);

}  // namespace covmap::fitting::detail
