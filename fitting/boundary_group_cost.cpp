#include "fitting/boundary_group_cost.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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

// The residuals of a pair's samples and the Jacobian rows of the sides asked for, with Jets of N
// derivative slots: a's parameters in slots a_slot…a_slot+2, b's in b_slot…b_slot+2, a side with
// slot < 0 held (no slots). Each slot's arithmetic reads only that slot of its inputs (x86-64
// without FMA contraction, no reassociation), so a side's derivatives are the same, bit for bit,
// whether the other side has slots or not: Ceres' inner iterations hold every site but one and
// ask for one side only, which then costs half the slots. Returns Σρ.
template <int N>
double evaluate_with_jets(const std::vector<PairSample>& samples, const ceres::LossFunction* loss, const double* a,
                          const double* b, int a_slot, int b_slot, double* residuals, double* ja, double* jb) {
  using J = ceres::Jet<double, N>;
  J aj[kSiteBlockSize], bj[kSiteBlockSize];
  for (int k = 0; k < kSiteBlockSize; ++k) {
    aj[k] = a_slot < 0 ? J(a[k]) : J(a[k], a_slot + k);
    bj[k] = b_slot < 0 ? J(b[k]) : J(b[k], b_slot + k);
  }
  // w_a / w_b once for all the pair's samples (as each sample's functor would compute it).
  const J ratio = BoundaryResidual::weight_ratio(aj, bj);
  double sum_rho = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const PairSample& p = samples[i];
    J rj;
    BoundaryResidual(p.x, p.y, p.scale).with_ratio(aj, bj, ratio, &rj);
    const double s = rj.a * rj.a;
    double rho[3] = {s, 1.0, 0.0};
    if (loss != nullptr) loss->Evaluate(s, rho);
    sum_rho += rho[0];
    const Correction c = correction(s, rho);
    residuals[i] = c.residual * rj.a;
    for (int k = 0; k < kSiteBlockSize; ++k) {
      if (ja != nullptr) ja[i * kSiteBlockSize + k] = c.jacobian * rj.v[a_slot + k];
      if (jb != nullptr) jb[i * kSiteBlockSize + k] = c.jacobian * rj.v[b_slot + k];
    }
  }
  return sum_rho;
}

}  // namespace

bool PairCost::Memo::holds(const double* a, const double* b) const {
  static_assert(std::tuple_size_v<decltype(at)> == kPairParameters);
  return !values.empty() && std::memcmp(at.data(), a, sizeof(double) * kSiteBlockSize) == 0 &&
         std::memcmp(at.data() + kSiteBlockSize, b, sizeof(double) * kSiteBlockSize) == 0;
}

void PairCost::Memo::keep(const double* a, const double* b, const double* residuals, const double* ja, const double* jb,
                          std::size_t rows, double sum_rho) {
  std::copy(a, a + kSiteBlockSize, at.begin());
  std::copy(b, b + kSiteBlockSize, at.begin() + kSiteBlockSize);
  const std::size_t entries = rows * kSiteBlockSize;
  values.resize(rows + 2 * entries);
  std::copy(residuals, residuals + rows, values.begin());
  std::copy(ja, ja + entries, values.begin() + rows);
  std::copy(jb, jb + entries, values.begin() + rows + entries);
  rho = sum_rho;
}

void PairCost::Memo::copy_to(double* residuals, double* ja, double* jb) const {
  const std::size_t rows = values.size() / (1 + 2 * kSiteBlockSize), entries = rows * kSiteBlockSize;
  std::copy(values.begin(), values.begin() + rows, residuals);
  std::copy(values.begin() + rows, values.begin() + rows + entries, ja);
  std::copy(values.begin() + rows + entries, values.end(), jb);
}

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
  // The same Jets as ceres::AutoDiffCostFunction<BoundaryResidual, 1, 3, 3> (a's parameters in
  // derivative slots 0–2, b's in 3–5) when both sides are asked for; one side's alone otherwise.
  if (ja != nullptr && jb != nullptr) {
    if (memo_.holds(a, b)) {
      memo_.copy_to(residuals, ja, jb);
      last_rho_ = memo_.rho;
      return true;
    }
    last_rho_ = evaluate_with_jets<kPairParameters>(samples_, loss_, a, b, 0, kSiteBlockSize, residuals, ja, jb);
    memo_.keep(a, b, residuals, ja, jb, samples_.size(), last_rho_);
    return true;
  }
  if (ja != nullptr || jb != nullptr) {
    last_rho_ = evaluate_with_jets<kSiteBlockSize>(samples_, loss_, a, b, ja != nullptr ? 0 : -1, jb != nullptr ? 0 : -1,
                                                   residuals, ja, jb);
    return true;
  }
  const double ratio = BoundaryResidual::weight_ratio(a, b);
  double sum_rho = 0.0;
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const PairSample& p = samples_[i];
    double r = 0.0;
    BoundaryResidual(p.x, p.y, p.scale).with_ratio(a, b, ratio, &r);
    const double s = r * r;
    double rho[3] = {s, 1.0, 0.0};
    if (loss_ != nullptr) loss_->Evaluate(s, rho);
    sum_rho += rho[0];
    residuals[i] = correction(s, rho).residual * r;
  }
  last_rho_ = sum_rho;
  return true;
}

}  // namespace covmap::fitting::detail
