// Per-site 1-σ uncertainty of the refined sites (ceres::Covariance of each site's [x, y, u] block).
//
// The covariance problem repeats the solved problem without the loss, each sample residual scaled
// by √(w_i / κ): w_i the IRLS weight ρ'(r_i²) at the solution, κ the noise variance factor
// (fitting/robust_loss.h: from the estimated noise level when σ are nominal, from N(0, 1) when
// calibrated). Priors enter unscaled (their σ are calibrated by contract). Without priors this
// is κ (Σ w J'J)⁻¹, the M-estimator's covariance; with priors, the data and priors are combined in
// proportion to their precisions.
//
// Rank deficiency: the sparse QR fails on a rank-deficient Jacobian. The undetermined sites are
// then found from J'J with its columns scaled to unit norm (so lengths and log weights compare):
// first each site's own block (its neighbours held; finds sites with too few samples, at any size),
// then, if that was not all, the whole matrix (up to tolerance::kMaxDenseDiagnosisParameters; finds
// deficiencies shared by several sites, e.g. two sites seen only through their common bisector).
// Undetermined sites get +inf sigmas and are held fixed while the covariance of the others is
// computed again — conditional on them, which is the best the data can say.
#pragma once

#include <span>
#include <string>
#include <vector>

#include <ceres/loss_function.h>

#include "fitting/problem_setup.h"

namespace covmap::fitting::detail {

struct CovarianceOutcome {
  std::vector<SiteUncertainty> uncertainty;  // per site; sites without samples are left default
  double variance_factor = 1.0;              // κ
  std::string remark;                        // empty, or why some or all are unavailable
  double log_range_sigma = 0.0;              // 1-σ of ρ = log R (layout.range), 0 if not computed
};

// The solved problem as the covariance reads it: its layout, data and loss, and the sample
// residuals at the solution (σ units).
struct SolvedProblem {
  const Layout& layout;
  std::span<const BoundarySample> samples;
  std::span<const SitePrior> priors;
  const ceres::LossFunction* loss = nullptr;
  std::span<const double> residuals;
};

// `blocks` (and `log_range`, when layout.range) hold the solution.
CovarianceOutcome site_covariance(std::vector<SiteBlock>& blocks, double* log_range, const SolvedProblem& solved,
                                  const RefineOptions& options);

}  // namespace covmap::fitting::detail
