// Preconditioned conjugate gradients for the least-squares solves of recognize()
// (position_solve.cpp: Jacobi; weight_solve.cpp: multigrid, laplacian_multigrid.h): A x = b for a
// symmetric positive semi-definite A given as a function, over real (double) or real-linear complex
// (std::complex<double>) unknowns. With Jacobi, rows whose diagonal is 0 are frozen (their unknowns
// keep their value: faces without arcs, or held fixed).
// Internal to the recognition library.
#pragma once

#include <algorithm>
#include <complex>
#include <cstddef>

#include "core/large_buffer.h"
#include "recognition/tolerances.h"

namespace covmap::recognition::stages {

template <class T>
double real_dot(const LargeVector<T>& a, const LargeVector<T>& b) {
  double sum = 0.0;  // in order: the same whatever the number of workers
  for (std::size_t k = 0; k < a.size(); ++k) sum += std::real(std::conj(a[k]) * b[k]);
  return sum;
}

// From x with residual r = b - A x (both updated in place), preconditioned by `precondition(r, z)`
// (z = M⁻¹ r, M symmetric positive definite). Stops when the preconditioned residual rᵀM⁻¹r has
// shrunk by tolerance::kSolveReduction² or below `rz_floor` (its own rounding), or after
// tolerance::kSolveIterations applications of A; returns the number of iterations made. `apply(p,
// q)` sets q = A p. `flexible`: the preconditioner varies from call to call (a K-cycle), and the
// directions are kept conjugate by the Polak-Ribière form of β (flexible conjugate gradients).
template <class T, class Apply, class Precondition>
int preconditioned_conjugate_gradients(const Apply& apply, const Precondition& precondition, LargeVector<T>& x,
                                       LargeVector<T>& r, double rz_floor, bool flexible = false) {
  const std::size_t n = x.size();
  LargeVector<T> z(n), p(n), q(n), z_last(flexible ? n : 0);
  precondition(r, z);
  p = z;
  double rz = real_dot(r, z);
  const double goal = std::max(tolerance::kSolveReduction * tolerance::kSolveReduction * rz, rz_floor);
  int it = 0;
  for (; it < tolerance::kSolveIterations && rz > goal; ++it) {
    apply(p, q);
    const double pq = real_dot(p, q);
    if (!(pq > 0)) break;
    const double alpha = rz / pq;
    for (std::size_t f = 0; f < n; ++f) x[f] += alpha * p[f], r[f] -= alpha * q[f];
    if (flexible) z_last = z;
    precondition(r, z);
    const double rz_next = real_dot(r, z);
    const double beta = (flexible ? rz_next - real_dot(r, z_last) : rz_next) / rz;
    rz = rz_next;
    for (std::size_t f = 0; f < n; ++f) p[f] = z[f] + beta * p[f];
  }
  return it;
}

// Jacobi preconditioning: rows whose diagonal is 0 are frozen (their unknowns keep their value).
template <class T, class Apply>
int conjugate_gradients(const Apply& apply, const LargeVector<double>& diag, LargeVector<T>& x, LargeVector<T>& r,
                        double rz_floor = 0.0) {
  const std::size_t n = x.size();
  for (std::size_t f = 0; f < n; ++f)
    if (!(diag[f] > 0)) r[f] = T(0.0);
  auto frozen_apply = [&](const LargeVector<T>& in, LargeVector<T>& out) {
    apply(in, out);
    for (std::size_t f = 0; f < n; ++f)
      if (!(diag[f] > 0)) out[f] = T(0.0);
  };
  auto jacobi = [&](const LargeVector<T>& in, LargeVector<T>& out) {
    for (std::size_t f = 0; f < n; ++f) out[f] = diag[f] > 0 ? in[f] / diag[f] : T(0.0);
  };
  return preconditioned_conjugate_gradients(frozen_apply, jacobi, x, r, rz_floor);
}

}  // namespace covmap::recognition::stages
