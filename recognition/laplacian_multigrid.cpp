#include "recognition/laplacian_multigrid.h"

#include <cmath>
#include <utility>

#include "core/parallel.h"
#include "recognition/tolerances.h"

namespace covmap::recognition::stages {
namespace {

// Each unknown paired with its unmatched neighbour of largest weight (ties: the lower index), in
// index order; an unknown whose neighbours are all taken joins the pair of its strongest neighbour
// (a lone unknown per pair would leave most of a planar graph's unknowns uncoarsened after a few
// levels). Returns the number of aggregates.
int match_pairs(const GroundedLaplacian& a, LargeVector<int>& aggregate) {
  const std::size_t n = a.size();
  constexpr int kFree = -1, kLeft = -2;
  aggregate.assign(n, kFree);
  int count = 0;
  for (std::size_t f = 0; f < n; ++f) {
    if (aggregate[f] != kFree) continue;
    int best = -1;
    for (int k = a.begin[f]; k < a.begin[f + 1]; ++k)
      if (aggregate[a.other[k]] == kFree && a.other[k] != static_cast<int>(f) && (best < 0 || a.weight[k] > a.weight[best]))
        best = k;
    if (best < 0) {
      aggregate[f] = kLeft;
      continue;
    }
    aggregate[f] = aggregate[a.other[best]] = count++;
  }
  for (std::size_t f = 0; f < n; ++f) {
    if (aggregate[f] != kLeft) continue;
    int best = -1;
    for (int k = a.begin[f]; k < a.begin[f + 1]; ++k)
      if (aggregate[a.other[k]] >= 0 && (best < 0 || a.weight[k] > a.weight[best])) best = k;
    aggregate[f] = best >= 0 ? aggregate[a.other[best]] : count++;
  }
  return count;
}

// Pᵀ A P for the piecewise-constant prolongation of `aggregate`: edges between aggregates summed,
// edges inside one dropped, excess summed. The diagonal is rebuilt from the summed edges and excess
// (not as a difference, which would drown a small excess in the rounding of the edge weights).
GroundedLaplacian galerkin(const GroundedLaplacian& a, const LargeVector<int>& aggregate, int count) {
  const std::size_t n = a.size();
  LargeVector<int> member_begin(static_cast<std::size_t>(count) + 1, 0), member(n);
  for (std::size_t f = 0; f < n; ++f) ++member_begin[aggregate[f] + 1];
  for (int c = 0; c < count; ++c) member_begin[c + 1] += member_begin[c];
  LargeVector<int> fill(member_begin.begin(), member_begin.end() - 1);
  for (std::size_t f = 0; f < n; ++f) member[fill[aggregate[f]]++] = static_cast<int>(f);

  GroundedLaplacian c;
  c.begin.assign(static_cast<std::size_t>(count) + 1, 0);
  c.excess.assign(count, 0.0);
  LargeVector<int> slot(count, -1);  // per coarse unknown: its position in the row being built
  std::vector<int> other;
  std::vector<double> weight;
  other.reserve(a.other.size() / 2), weight.reserve(a.other.size() / 2);
  for (int row = 0; row < count; ++row) {
    const std::size_t row_begin = other.size();
    for (int m = member_begin[row]; m < member_begin[row + 1]; ++m) {
      const int f = member[m];
      c.excess[row] += a.excess[f];
      for (int k = a.begin[f]; k < a.begin[f + 1]; ++k) {
        const int col = aggregate[a.other[k]];
        if (col == row) continue;
        if (slot[col] < 0) slot[col] = static_cast<int>(other.size()), other.push_back(col), weight.push_back(0.0);
        weight[slot[col]] += a.weight[k];
      }
    }
    for (std::size_t k = row_begin; k < other.size(); ++k) slot[other[k]] = -1;
    c.begin[row + 1] = static_cast<int>(other.size());
  }
  c.other.assign(other.begin(), other.end());
  c.weight.assign(weight.begin(), weight.end());
  c.finish();
  return c;
}

// Dense Cholesky A = R Rᵀ in place (lower triangle, row-major); false when A is not positive definite.
bool cholesky(std::vector<double>& m, std::size_t n) {
  for (std::size_t j = 0; j < n; ++j) {
    double d = m[j * n + j];
    for (std::size_t k = 0; k < j; ++k) d -= m[j * n + k] * m[j * n + k];
    if (!(d > 0)) return false;
    m[j * n + j] = std::sqrt(d);
    for (std::size_t i = j + 1; i < n; ++i) {
      double s = m[i * n + j];
      for (std::size_t k = 0; k < j; ++k) s -= m[i * n + k] * m[j * n + k];
      m[i * n + j] = s / m[j * n + j];
    }
  }
  return true;
}

double dot(const LargeVector<double>& a, const LargeVector<double>& b) {
  double sum = 0.0;  // in order: the same whatever the number of workers
  for (std::size_t k = 0; k < a.size(); ++k) sum += a[k] * b[k];
  return sum;
}

// One Gauss-Seidel sweep on A z = r, forward or backward.
void gauss_seidel(const GroundedLaplacian& a, const LargeVector<double>& r, LargeVector<double>& z, bool forward) {
  const std::size_t n = a.size();
  for (std::size_t step = 0; step < n; ++step) {
    const std::size_t f = forward ? step : n - 1 - step;
    double sum = r[f];
    for (int k = a.begin[f]; k < a.begin[f + 1]; ++k) sum += a.weight[k] * z[a.other[k]];
    z[f] = sum / a.diag[f];
  }
}

}  // namespace

void GroundedLaplacian::finish() {
  const std::size_t n = excess.size();
  diag.assign(n, 0.0);
  for (std::size_t f = 0; f < n; ++f) {
    double sum = excess[f];
    for (int k = begin[f]; k < begin[f + 1]; ++k) sum += weight[k];
    diag[f] = sum;
  }
}

void GroundedLaplacian::apply(const LargeVector<double>& x, LargeVector<double>& y) const {
  const std::size_t n = size();
  parallel_chunks(n, worker_count(n), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t f = b; f < e; ++f) {
      double sum = diag[f] * x[f];
      for (int k = begin[f]; k < begin[f + 1]; ++k) sum -= weight[k] * x[other[k]];
      y[f] = sum;
    }
  });
}

LaplacianMultigrid::LaplacianMultigrid(GroundedLaplacian fine) {
  levels_.push_back(std::move(fine));
  while (levels_.back().size() > tolerance::kCoarsestUnknowns) {
    // Two rounds of pairing per level: aggregates of up to four.
    const GroundedLaplacian& a = levels_.back();
    LargeVector<int> first, second;
    const int pairs = match_pairs(a, first);
    const GroundedLaplacian half = galerkin(a, first, pairs);
    const int count = match_pairs(half, second);
    if (count > tolerance::kCoarsening * static_cast<double>(a.size())) break;  // no graph left to coarsen
    for (int& g : first) g = second[g];
    GroundedLaplacian coarse = galerkin(half, second, count);
    aggregate_.push_back(std::move(first));
    levels_.push_back(std::move(coarse));
  }
  work_.resize(levels_.size());
  for (std::size_t l = 0; l + 1 < levels_.size(); ++l) {
    const std::size_t n = levels_[l].size(), coarse = levels_[l + 1].size();
    work_[l].residual.resize(n), work_[l].rc.resize(coarse), work_[l].zc.resize(coarse);
    if (l > 0) for (auto* v : {&work_[l].c1, &work_[l].v1, &work_[l].c2, &work_[l].v2, &work_[l].rest}) v->resize(n);
  }
  const GroundedLaplacian& last = levels_.back();
  const std::size_t n = last.size();
  if (n <= tolerance::kCoarsestUnknowns) {
    coarsest_factor_.assign(n * n, 0.0);
    for (std::size_t f = 0; f < n; ++f) {
      coarsest_factor_[f * n + f] = last.diag[f];
      for (int k = last.begin[f]; k < last.begin[f + 1]; ++k) coarsest_factor_[f * n + last.other[k]] -= last.weight[k];
    }
    factored_ = cholesky(coarsest_factor_, n);
  }
}

void LaplacianMultigrid::solve_coarsest(const LargeVector<double>& r, LargeVector<double>& z) const {
  const GroundedLaplacian& a = levels_.back();
  const std::size_t n = a.size();
  if (!factored_) {  // a level that would not coarsen, or not definite: smoothing only
    for (std::size_t f = 0; f < n; ++f) z[f] = 0.0;
    gauss_seidel(a, r, z, true);
    gauss_seidel(a, r, z, false);
    return;
  }
  const std::vector<double>& m = coarsest_factor_;
  for (std::size_t i = 0; i < n; ++i) {  // R y = r, then Rᵀ z = y
    double s = r[i];
    for (std::size_t k = 0; k < i; ++k) s -= m[i * n + k] * z[k];
    z[i] = s / m[i * n + i];
  }
  for (std::size_t i = n; i-- > 0;) {
    double s = z[i];
    for (std::size_t k = i + 1; k < n; ++k) s -= m[k * n + i] * z[k];
    z[i] = s / m[i * n + i];
  }
}

void LaplacianMultigrid::cycle(std::size_t level, const LargeVector<double>& r, LargeVector<double>& z) const {
  if (level + 1 == levels_.size()) return solve_coarsest(r, z);
  const GroundedLaplacian& a = levels_[level];
  const LargeVector<int>& aggregate = aggregate_[level];
  const std::size_t n = a.size(), coarse = levels_[level + 1].size();
  for (std::size_t f = 0; f < n; ++f) z[f] = 0.0;
  gauss_seidel(a, r, z, true);
  Work& w = work_[level];
  LargeVector<double>&residual = w.residual, &rc = w.rc, &zc = w.zc;
  a.apply(z, residual);
  for (std::size_t c = 0; c < coarse; ++c) rc[c] = 0.0;
  for (std::size_t f = 0; f < n; ++f) rc[aggregate[f]] += r[f] - residual[f];
  coarse_correction(level + 1, rc, zc);
  for (std::size_t f = 0; f < n; ++f) z[f] += zc[aggregate[f]];
  gauss_seidel(a, r, z, false);
}

// The K-cycle: on a level above the coarsest, A e = r is solved by two steps of flexible conjugate
// gradients preconditioned by the next cycle (the second only when the first left more than
// kKCycleResidual of the residual), instead of one cycle: a V-cycle of piecewise-constant
// aggregates loses a constant factor per level, the Krylov step wins it back.
void LaplacianMultigrid::coarse_correction(std::size_t level, const LargeVector<double>& r, LargeVector<double>& z) const {
  if (level + 1 == levels_.size()) return solve_coarsest(r, z);
  const GroundedLaplacian& a = levels_[level];
  const std::size_t n = a.size();
  Work& w = work_[level];
  LargeVector<double>&c1 = w.c1, &v1 = w.v1, &rest = w.rest, &c2 = w.c2, &v2 = w.v2;
  cycle(level, r, c1);
  a.apply(c1, v1);
  const double rho1 = dot(c1, v1), alpha1 = dot(c1, r) / rho1;
  for (std::size_t f = 0; f < n; ++f) rest[f] = r[f] - alpha1 * v1[f];
  if (!(rho1 > 0) || dot(rest, rest) <= tolerance::kKCycleResidual * tolerance::kKCycleResidual * dot(r, r)) {
    for (std::size_t f = 0; f < n; ++f) z[f] = rho1 > 0 ? alpha1 * c1[f] : c1[f];
    return;
  }
  cycle(level, rest, c2);
  a.apply(c2, v2);
  const double gamma = dot(c2, v1), beta = dot(c2, v2) - gamma * gamma / rho1, alpha2 = dot(c2, rest) / beta;
  if (!(beta > 0)) {
    for (std::size_t f = 0; f < n; ++f) z[f] = alpha1 * c1[f];
    return;
  }
  const double first = alpha1 - gamma * alpha2 / rho1;
  for (std::size_t f = 0; f < n; ++f) z[f] = first * c1[f] + alpha2 * c2[f];
}

void LaplacianMultigrid::precondition(const LargeVector<double>& r, LargeVector<double>& z) const { cycle(0, r, z); }

}  // namespace covmap::recognition::stages
