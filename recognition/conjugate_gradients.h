// Jacobi-preconditioned conjugate gradients for the least-squares solves of recognize()
// (position_solve.cpp, weight_solve.cpp): A x = b for a symmetric positive semi-definite A given as
// a function, over real (double) or real-linear complex (std::complex<double>) unknowns. Rows whose
// diagonal is 0 are frozen (their unknowns keep their value: faces without arcs, or held fixed).
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

// From x with residual r = b - A x (both updated in place). Stops when the preconditioned
// residual has shrunk by tolerance::kSolveReduction or below `rz_floor` (its own rounding), or after
// tolerance::kSolveIterations applications of A. `apply(p, q)` sets q = A p.
template <class T, class Apply>
void conjugate_gradients(const Apply& apply, const LargeVector<double>& diag, LargeVector<T>& x, LargeVector<T>& r,
                         double rz_floor = 0.0) {
  const std::size_t n = x.size();
  LargeVector<T> z(n), p(n), q(n);
  auto precondition = [&] {
    for (std::size_t f = 0; f < n; ++f) z[f] = diag[f] > 0 ? r[f] / diag[f] : T(0.0);
  };
  for (std::size_t f = 0; f < n; ++f)
    if (!(diag[f] > 0)) r[f] = T(0.0);
  precondition();
  p = z;
  double rz = real_dot(r, z);
  const double goal = std::max(tolerance::kSolveReduction * tolerance::kSolveReduction * rz, rz_floor);
  for (int it = 0; it < tolerance::kSolveIterations && rz > goal; ++it) {
    apply(p, q);
    for (std::size_t f = 0; f < n; ++f)
      if (!(diag[f] > 0)) q[f] = T(0.0);
    const double pq = real_dot(p, q);
    if (!(pq > 0)) break;
    const double alpha = rz / pq;
    for (std::size_t f = 0; f < n; ++f) x[f] += alpha * p[f], r[f] -= alpha * q[f];
    precondition();
    const double rz_next = real_dot(r, z);
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t f = 0; f < n; ++f) p[f] = z[f] + beta * p[f];
  }
}

}  // namespace covmap::recognition::stages
