// The robust loss on sample residuals and the noise statistics that follow from it.
//
// Residuals r are in σ units; the loss ρ acts on s = r² (Ceres' convention; cost ½ρ(s)), with its
// scale c (RefineOptions::loss_scale) in σ units too. At the solution, ceres::Covariance of the
// robust problem would be (Σ w_i J_i'J_i)⁻¹ with w = ρ'(r²) — for Huber and Cauchy ρ'' ≤ 0, so
// Ceres' corrector only rescales by √ρ' — the inverse of the reweighted information, not the
// M-estimator's covariance. Under homogeneous errors r ~ N(0, s²) (Huber, Robust Statistics,
// 1981, §7.6) the M-estimator's covariance is
//     E[ψ²] / E[ψ']² · (J'J)⁻¹,   ψ(r) = r ρ'(r²),  ψ'(r) = ρ'(r²) + 2 r² ρ''(r²),
// and Σ w J'J ≈ E[w] J'J, so it equals κ (Σ w J'J)⁻¹ with the variance factor
//     κ = E[w] · E[ψ²] / E[ψ']² = s² · V(c / s),
// V(c') being the same expression for N(0, 1) and a loss of scale c' (model_variance_factor).
//  - σ calibrated: s = 1, κ = V(c).
//  - σ nominal: s is estimated. Plain least squares uses the reduced chi-square, κ = Σr²/(m − p),
//    which is what its (outlier-sensitive) estimate really scatters with. Robust losses use a robust
//    s (Huber's proposal 2, below), so a few gross outliers neither inflate κ nor need to be
//    modelled. (The per-sample sandwich Σψ²/(Σψ')² scatters more for Cauchy, whose ψ' changes
//    sign among the inliers; docs/FITTING.md has the measurements.)
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>

#include <ceres/loss_function.h>

#include "fitting/refine.h"

namespace covmap::fitting::detail {

// Huber's proposal 2 scale: s solves Σ min((r_i/s)², k²) = (m − p) E[min(Z², k²)], Z ~ N(0, 1).
// k = 1.5 is Huber's own choice: ~95% of Gaussian residuals are untouched, so s is nearly as
// precise as the RMS, while a residual far out counts as k² only.
inline constexpr double kScaleClip = 1.5;

// nullptr for RobustLoss::kNone; `scale` in σ units. The Cauchy loss evaluates ρ with log1p, so its
// cost stays exact for residuals far below the scale (Ceres' own rounds ρ to 0 below ~1e-8 c, which
// stops the solver early on near-exact data).
std::unique_ptr<ceres::LossFunction> make_loss(RobustLoss loss, double scale);

struct LossDerivatives {
  double weight = 1.0;  // w = ρ'(r²), the IRLS weight
  double psi = 0.0;     // ψ(r) = r w
  double dpsi = 1.0;    // ψ'(r)
};

// loss may be nullptr (plain least squares).
LossDerivatives loss_at(const ceres::LossFunction* loss, double r);

// V(scale) = E[w] E[ψ²] / E[ψ']² for r ~ N(0, 1), by quadrature; 1 for RobustLoss::kNone.
double model_variance_factor(RobustLoss loss, double scale);

// Huber's proposal 2 scale of the residuals with `free_parameters` fitted; 0 if all are 0.
double robust_noise_scale(std::span<const double> r, std::size_t free_parameters);

struct VarianceFactor {
  double value = 1.0;
  bool ok = true;
  std::string problem;  // why not ok
};

// κ for nominal σ, from the sample residuals r (σ units) with `free_parameters` parameters fitted.
VarianceFactor estimate_variance_factor(RobustLoss loss, double scale, std::span<const double> r,
                                        std::size_t free_parameters);

}  // namespace covmap::fitting::detail
