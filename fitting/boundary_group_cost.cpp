#include "fitting/boundary_group_cost.h"

#include <cmath>
#include <utility>

#include <ceres/jet.h>

#include "fitting/residuals.h"

namespace covmap::fitting::detail {
namespace {

constexpr int kPairParameters = 2 * kSiteBlockSize;
using PairJet = ceres::Jet<double, kPairParameters>;

// How Ceres' Corrector changes a one-residual block under a loss with derivatives rho at s = r²:
// the residual is multiplied by `residual`, its Jacobian row by `jacobian`.
struct Correction {
  double residual = 1.0, jacobian = 1.0;
};

Correction correction(double s, const double rho[3]) {
  const double sqrt_rho1 = std::sqrt(rho[1]);
  // As Ceres: no curvature term at r = 0 or where ρ″ ≤ 0 (Huber's and Cauchy's outlier side).
  if (s == 0.0 || rho[2] <= 0.0) return {sqrt_rho1, sqrt_rho1};
  const double alpha = 1.0 - std::sqrt(1.0 + 2.0 * s * rho[2] / rho[1]);
  return {sqrt_rho1 / (1.0 - alpha), sqrt_rho1 * (1.0 - alpha)};
}

}  // namespace

PairCost::PairCost(std::vector<PairSample> samples, const ceres::LossFunction* loss)
    : samples_(std::move(samples)), loss_(loss) {
  set_num_residuals(static_cast<int>(samples_.size()));
  mutable_parameter_block_sizes()->push_back(kSiteBlockSize);
  mutable_parameter_block_sizes()->push_back(kSiteBlockSize);
}

bool PairCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const double* a = parameters[0];
  const double* b = parameters[1];
  double* ja = jacobians != nullptr ? jacobians[0] : nullptr;
  double* jb = jacobians != nullptr ? jacobians[1] : nullptr;
  const bool derivatives = ja != nullptr || jb != nullptr;
  // The same Jets as ceres::AutoDiffCostFunction<BoundaryResidual, 1, 3, 3>: a's parameters are
  // derivative slots 0–2, b's 3–5.
  PairJet aj[kSiteBlockSize], bj[kSiteBlockSize];
  if (derivatives) {
    for (int k = 0; k < kSiteBlockSize; ++k) {
      aj[k] = PairJet(a[k], k);
      bj[k] = PairJet(b[k], kSiteBlockSize + k);
    }
  }
  // w_a / w_b once for all the pair's samples (as each sample's functor would compute it).
  const PairJet ratio_jet = derivatives ? BoundaryResidual::weight_ratio(aj, bj) : PairJet();
  const double ratio = derivatives ? 0.0 : BoundaryResidual::weight_ratio(a, b);
  double sum_rho = 0.0;
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const PairSample& p = samples_[i];
    const BoundaryResidual residual(p.x, p.y, p.scale);
    double r = 0.0;
    PairJet rj;
    if (derivatives) {
      residual.with_ratio(aj, bj, ratio_jet, &rj);
      r = rj.a;
    } else {
      residual.with_ratio(a, b, ratio, &r);
    }
    const double s = r * r;
    double rho[3] = {s, 1.0, 0.0};
    if (loss_ != nullptr) loss_->Evaluate(s, rho);
    sum_rho += rho[0];
    const Correction c = correction(s, rho);
    residuals[i] = c.residual * r;
    for (int k = 0; k < kSiteBlockSize; ++k) {
      if (ja != nullptr) ja[i * kSiteBlockSize + k] = c.jacobian * rj.v[k];
      if (jb != nullptr) jb[i * kSiteBlockSize + k] = c.jacobian * rj.v[kSiteBlockSize + k];
    }
  }
  last_rho_ = sum_rho;
  return true;
}

}  // namespace covmap::fitting::detail
