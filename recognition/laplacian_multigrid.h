// Aggregation multigrid for grounded graph Laplacians: the preconditioner of the weight solve
// (weight_solve.cpp). Internal to the recognition library.
//
// A grounded Laplacian is A = L + E on n unknowns: L the Laplacian of a graph with positive edge
// weights, E ≥ 0 diagonal (the weights of edges to unknowns held fixed). It is positive definite
// when every connected component has some E > 0 — the caller's duty; a component without one makes
// the coarsest factorisation fail, and the coarsest level is then only smoothed (a weaker but still
// symmetric preconditioner).
//
// Why: Jacobi-preconditioned conjugate gradients on a planar graph's Laplacian need O(√n)
// iterations (its condition grows like n), and the weight solve of 10^6 faces started far from the
// answer did not converge in 100. A cycle over a hierarchy of aggregates makes the iteration count
// almost independent of n (grid Laplacians 16 times apart in size: 48 and 56 iterations with weights
// spread over 1e4, 15 and 15 with equal weights). Levels are built by matching each unknown with
// the neighbour it is most strongly tied to, twice per level (aggregates of about four; planar
// graphs shrink about five-fold), and the coarse matrix is the exact Galerkin product Pᵀ A P of
// the piecewise-constant prolongation P — again a grounded Laplacian. Smoothing is one Gauss-Seidel
// sweep forward before the coarse correction and one backward after. Below the finest level the
// coarse problem is solved by up to two steps of flexible conjugate gradients (a K-cycle, Notay):
// piecewise-constant aggregates lose a constant factor per level in a plain V-cycle (23 and 50
// iterations on the equal-weight grids above). The preconditioner is therefore not a fixed linear
// map: the outer iteration must be flexible (conjugate_gradients.h). Everything runs in a fixed
// sequential order: the result does not depend on the number of workers.
#pragma once

#include <cstddef>
#include <vector>

#include "core/large_buffer.h"

namespace covmap::recognition::stages {

struct GroundedLaplacian {
  LargeVector<int> begin;      // per unknown + 1: its edges [begin[f], begin[f + 1])
  LargeVector<int> other;      // per edge: the unknown at its other end (each edge stored twice)
  LargeVector<double> weight;  // per edge: > 0
  LargeVector<double> excess;  // per unknown: ≥ 0
  LargeVector<double> diag;    // per unknown: Σ of its edges' weights + its excess (set by finish())
  std::size_t size() const { return diag.size(); }
  void finish();  // computes diag
  // y = A x (rows in parallel; each row summed in a fixed order).
  void apply(const LargeVector<double>& x, LargeVector<double>& y) const;
};

class LaplacianMultigrid {
 public:
  explicit LaplacianMultigrid(GroundedLaplacian fine);
  const GroundedLaplacian& matrix() const { return levels_.front(); }
  std::size_t levels() const { return levels_.size(); }
  // z = M⁻¹ r: one cycle from z = 0. Uses the object's work space: one call at a time.
  void precondition(const LargeVector<double>& r, LargeVector<double>& z) const;

 private:
  void cycle(std::size_t level, const LargeVector<double>& r, LargeVector<double>& z) const;
  void coarse_correction(std::size_t level, const LargeVector<double>& r, LargeVector<double>& z) const;
  void solve_coarsest(const LargeVector<double>& r, LargeVector<double>& z) const;

  std::vector<GroundedLaplacian> levels_;
  std::vector<LargeVector<int>> aggregate_;  // per level but the last: each unknown's on the next
  std::vector<double> coarsest_factor_;      // dense Cholesky factor of the last level (row-major)
  // Work space per level, allocated once (fresh pages cost more than the arithmetic at 10^6):
  // cycle's residual and the coarse right-hand side and correction; the K-cycle's two directions,
  // their images and the remaining residual.
  struct Work {
    LargeVector<double> residual, rc, zc, c1, v1, c2, v2, rest;
  };
  mutable std::vector<Work> work_;
  bool factored_ = false;
};

}  // namespace covmap::recognition::stages
