// The residuals of the site refinement, as small templated functors for ceres::AutoDiffCostFunction.
//
// Parameters: each site is one block [x, y, u] with u = log(weight), so weights stay positive
// without bounds and a common factor of all weights is a common shift of all u.
//
// BoundaryResidual — a point p observed on the bisector of sites a and b. With k = w_a / w_b,
//
//     f(p) = |p − a| − k |p − b|          (w_a times the difference of weighted distances)
//     r    = f(p) / |∇_p f(p)| / σ,        ∇_p f = (p − a)/|p − a| − k (p − b)/|p − b|
//
// f vanishes exactly on the bisector and f/|∇f| is its first-order (Sampson) distance from p: the
// signed length of the step along ∇f that reaches f = 0 in the linearisation. It is positive on b's
// side (p weighted-closer to b).
//
// Why not the exact distance to the Apollonius circle, ||p − c| − R|? Its centre and radius,
//     c = (a − k² b) / (1 − k²),   R = k |a − b| / |1 − k²|,
// blow up as k → 1, where the bisector becomes a line: the exact distance is a difference of two
// numbers ~1/|1 − k| that must cancel, so it loses all precision near equal weights and its
// derivatives with respect to the weights are singular there; equal-weight maps (and nearly equal
// weights, which are common) would need a separate line model and a switch between the two. f and
// ∇f above are polynomial in k and in the unit vectors toward the sites: smooth for every weight
// ratio, the same formula for circles and lines, and equal to the exact distance up to terms of
// order distance² × curvature (tests/fitting/residuals_test.cpp checks this against the closed
// form). Boundary samples lie within a few σ of the bisector, so the difference is negligible.
//
// The gradient norm is floored (tolerance::kGradientFloor) so the residual stays finite at the only
// points where ∇f = 0: off the bisector, on the line through equal-weight sites, outside them.
//
// RangeResidual — a point p observed on the range edge of site a, the circle of radius R·w_a about
// it (R common to the map, parameter ρ = log R):
//
//     r = (|p − a| − exp(ρ + u_a)) / σ
//
// the exact signed distance from the circle (positive outside the reach). A range edge never
// passes through its own site (the site is covered: distance 0 < R·w), so |p − a| > 0 there.
//
// PositionPriorResidual / LogWeightPriorResidual — independent Gaussian priors on a site's
// position (isotropic, σ in length units) and on its log weight.
#pragma once

#include <cmath>

#include <ceres/autodiff_cost_function.h>

#include "fitting/tolerances.h"

namespace covmap::fitting {

inline constexpr int kSiteBlockSize = 3;  // x, y, u = log(weight)
inline constexpr int kLogWeightIndex = 2;

class BoundaryResidual {
 public:
  // (px, py): the sample; scale: 1/σ (or any positive factor the residual is multiplied by).
  BoundaryResidual(double px, double py, double scale) : px_(px), py_(py), scale_(scale) {}

  template <typename T>
  bool operator()(const T* a, const T* b, T* residual) const {
    return with_ratio(a, b, weight_ratio(a, b), residual);
  }

  // k = w_a / w_b, which every sample between a and b shares (boundary_group_cost.cpp computes it
  // once per pair; the residual is the same to the bit).
  template <typename T>
  static T weight_ratio(const T* a, const T* b) {
    using std::exp;
    return exp(a[kLogWeightIndex] - b[kLogWeightIndex]);
  }

  template <typename T>
  bool with_ratio(const T* a, const T* b, const T& k, T* residual) const {
    using std::sqrt;
    const T ax = T(px_) - a[0], ay = T(py_) - a[1];
    const T bx = T(px_) - b[0], by = T(py_) - b[1];
    const T da = sqrt(ax * ax + ay * ay);
    const T db = sqrt(bx * bx + by * by);
    const T f = da - k * db;
    const T gx = ax / da - k * bx / db;
    const T gy = ay / da - k * by / db;
    const T floor = T(tolerance::kGradientFloor) * (T(1.0) + k);
    residual[0] = T(scale_) * f / sqrt(gx * gx + gy * gy + floor * floor);
    return true;
  }

  static ceres::CostFunction* Create(double px, double py, double scale) {
    return new ceres::AutoDiffCostFunction<BoundaryResidual, 1, kSiteBlockSize, kSiteBlockSize>(
        new BoundaryResidual(px, py, scale));
  }

 private:
  double px_, py_, scale_;
};

class RangeResidual {
 public:
  RangeResidual(double px, double py, double scale) : px_(px), py_(py), scale_(scale) {}

  template <typename T>
  bool operator()(const T* a, const T* log_range, T* residual) const {
    using std::exp;
    using std::sqrt;
    const T ax = T(px_) - a[0], ay = T(py_) - a[1];
    residual[0] = T(scale_) * (sqrt(ax * ax + ay * ay) - exp(log_range[0] + a[kLogWeightIndex]));
    return true;
  }

  static ceres::CostFunction* Create(double px, double py, double scale) {
    return new ceres::AutoDiffCostFunction<RangeResidual, 1, kSiteBlockSize, 1>(new RangeResidual(px, py, scale));
  }

 private:
  double px_, py_, scale_;
};

class PositionPriorResidual {
 public:
  PositionPriorResidual(double x, double y, double sigma) : x_(x), y_(y), inv_sigma_(1.0 / sigma) {}

  template <typename T>
  bool operator()(const T* site, T* residual) const {
    residual[0] = (site[0] - T(x_)) * T(inv_sigma_);
    residual[1] = (site[1] - T(y_)) * T(inv_sigma_);
    return true;
  }

  static ceres::CostFunction* Create(double x, double y, double sigma) {
    return new ceres::AutoDiffCostFunction<PositionPriorResidual, 2, kSiteBlockSize>(
        new PositionPriorResidual(x, y, sigma));
  }

 private:
  double x_, y_, inv_sigma_;
};

class LogWeightPriorResidual {
 public:
  LogWeightPriorResidual(double log_weight, double sigma) : u_(log_weight), inv_sigma_(1.0 / sigma) {}

  template <typename T>
  bool operator()(const T* site, T* residual) const {
    residual[0] = (site[kLogWeightIndex] - T(u_)) * T(inv_sigma_);
    return true;
  }

  static ceres::CostFunction* Create(double log_weight, double sigma) {
    return new ceres::AutoDiffCostFunction<LogWeightPriorResidual, 1, kSiteBlockSize>(
        new LogWeightPriorResidual(log_weight, sigma));
  }

 private:
  double u_, inv_sigma_;
};

}  // namespace covmap::fitting
