// All boundary samples between one pair of sites as one Ceres residual block, each sample under
// its own robust loss (internal to fitting/).
//
// Why. Ceres spends most of an evaluation on per-block bookkeeping, not on the residuals: with one
// block per sample (2·10⁵ one-row blocks on a 10⁴-sensor map) its preparation, validity checks and
// loss correction cost more than the automatic derivatives, and JᵀJ is assembled from 1×3 pieces.
// A pair's samples share both parameter blocks, so one block per pair holds the same Jacobian rows.
//
// What stays the same. Ceres applies a loss to a block's squared norm, which for a block of
// several samples is not the per-sample robust cost. So the loss is applied here, sample by sample,
// exactly as Ceres' Corrector applies it to a one-residual block: every residual and Jacobian row
// is the one the per-sample problem feeds the linear solver (the same automatic derivatives, the
// same √ρ′ scaling; the curvature term where ρ″ > 0), and the block's cost is Σ ½ρ(r²) through
// the block's loss: Ceres asks a block's loss for ρ right after evaluating the block, and
// PairLoss answers with the sum this cost function just computed (and ρ′ = 1, ρ″ = 0, so Ceres
// corrects nothing more). The problem solved is therefore the same; only the order of additions
// inside Ceres differs. A PairCost must not be evaluated by two threads at once (the solver runs
// on one; the covariance problem is built per sample without a loss).
//
// Evaluated again at the same point. With bounds on the log weights, every trust-region step of
// Ceres first evaluates the gradient at the candidate point (its projected line search), then the
// cost there, then, once the step is accepted, the Jacobian there again: the same residuals and
// Jacobian rows as the line search's, bit for bit. So a PairCost keeps its last evaluation with
// both sides' Jacobians and copies it when asked for the very same parameter values (compared bit
// for bit): the same numbers, without recomputing them. (Memory: seven doubles per sample.)
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/loss_function.h>

namespace covmap::fitting::detail {

struct PairSample {
  double x, y;   // the sample
  double scale;  // 1/σ (times any factor)
};

class PairCost final : public ceres::CostFunction {
 public:
  // loss: the per-sample robust loss (not owned; nullptr: plain least squares).
  PairCost(std::vector<PairSample> samples, const ceres::LossFunction* loss);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;
  // Σ ρ(r²) over the samples at the last evaluation (Σ r² without a loss).
  double last_rho() const { return last_rho_; }

 private:
  // The last evaluation with both Jacobians: its parameters, residuals and rows, and Σρ.
  struct Memo {
    std::array<double, 6> at{};
    std::vector<double> values;  // residuals, then a's Jacobian rows, then b's
    double rho = 0.0;
    bool holds(const double* a, const double* b) const;
    void keep(const double* a, const double* b, const double* residuals, const double* ja, const double* jb,
              std::size_t rows, double sum_rho);
    void copy_to(double* residuals, double* ja, double* jb) const;
  };

  std::vector<PairSample> samples_;
  const ceres::LossFunction* loss_;
  mutable double last_rho_ = 0.0;
  mutable Memo memo_;
};

// The block loss of a PairCost: ρ = its last Σρ, ρ′ = 1, ρ″ = 0.
class PairLoss final : public ceres::LossFunction {
 public:
  explicit PairLoss(const PairCost* cost) : cost_(cost) {}
  void Evaluate(double, double rho[3]) const override {
    rho[0] = cost_->last_rho();
    rho[1] = 1.0;
    rho[2] = 0.0;
  }

 private:
  const PairCost* cost_;
};

}  // namespace covmap::fitting::detail
