// Weight solve in recognize(): the log-weights of all faces by weighted least squares over every
// arc. Each arc with sites s_l, s_r on its two sides states their weight ratio (Lemma 1:
// w_l / w_r = |c - s_l| / r = r / |c - s_r|, equal weights for a line); breadth-first propagation
// uses only the arcs of one spanning tree, so its weights carry the sum of the rounding along the
// tree path (~√depth crossings, 4e-11 relative at 10^4 sites, 2.5e-8 at 10^6). Here every arc
// counts: minimise Σ ω_a (u_r - u_l - d_a)² over u = log w, a graph-Laplacian system solved by
// Jacobi-preconditioned conjugate gradients, started from the ratios integrated along the tree again
// from the refined sites.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.h"
#include "mobius/bisector_relation.h"
#include "recognition/conjugate_gradients.h"
#include "recognition/recognize_stages.h"
#include "recognition/tolerances.h"

namespace covmap::recognition::stages {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The arcs between assigned faces as a symmetric adjacency (CSR): per face its neighbours across
// arcs, the arcs' weights ω and the stated log-ratios d (u_neighbour - u_face ≈ d).
struct ArcSystem {
  LargeVector<int> begin;  // per face + 1
  LargeVector<int> other;
  LargeVector<double> omega, d;
};

// log(w_r / w_l) from both sites, and how much the arc is trusted. Relative to a node v of the arc
// (bisector_relation.h): |c - s| = |γ - δ|. Averaging the two forms of Lemma 1 uses both sites.
// The error of log|c - s| is the sites' position error over |c - s|; arcs whose centre lies far
// from the sites compared with their spacing (nearly equal weights; lines in the limit) are the
// most accurate and weigh up to kMaxArcWeight.
std::pair<double, double> arc_ratio(const mobius::ArcBisector& b, mobius::Complex sl, mobius::Complex sr) {
  if (b.line) return {0.0, tolerance::kMaxArcWeight};
  const double dl = std::abs(b.gamma - (sl - b.v)), dr = std::abs(b.gamma - (sr - b.v));
  const double spacing = std::abs(sr - sl);
  const double m = spacing > 0 ? std::min(dl, dr) / spacing : tolerance::kMaxArcWeight;
  return {0.5 * std::log(dr / dl), std::clamp(m * m, 1.0, tolerance::kMaxArcWeight)};
}

ArcSystem arc_system(const TracedGraph& t, const SolveOrder& order, const LargeVector<FaceSite>& site) {
  const Diagram& g = t.g;
  const std::size_t faces = order.order.size();
  ArcSystem s;
  s.begin.assign(faces + 1, 0);
  // l, r: the two faces; ul, ur: their unknowns.
  int ul = kNone, ur = kNone;
  auto usable = [&](std::size_t a, int& l, int& r) {
    l = t.face_of_half[2 * a], r = t.face_of_half[2 * a + 1];
    if (g.arcs[a].frame || l == kNone || r == kNone || l == r) return false;
    ul = order.rank[l], ur = order.rank[r];
    return ul != kNone && ur != kNone;
  };
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    int l, r;
    if (usable(a, l, r)) ++s.begin[ul + 1], ++s.begin[ur + 1];
  }
  for (std::size_t f = 0; f < faces; ++f) s.begin[f + 1] += s.begin[f];
  s.other.resize(s.begin[faces]);
  s.omega.resize(s.begin[faces]);
  s.d.resize(s.begin[faces]);
  LargeVector<int> fill(s.begin.begin(), s.begin.end() - 1);
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    int l, r;
    if (!usable(a, l, r)) continue;
    const mobius::ArcBisector b = mobius::arc_bisector(g.arcs[a], g.nodes, site[l].position);
    auto [d, omega] = arc_ratio(b, site[l].position, site[r].position);
    // As in the position solve: an arc through a far node is stated only to that distance's rounding.
    const double far = 1.0 + t.extent.distance_to({b.v.real(), b.v.imag()}) / t.scale;
    omega /= far * far;
    if (!std::isfinite(d)) d = 0.0, omega = 0.0;  // a site at its arc's centre: the arc states nothing
    s.other[fill[ul]] = ur, s.omega[fill[ul]] = omega, s.d[fill[ul]++] = d;
    s.other[fill[ur]] = ul, s.omega[fill[ur]] = omega, s.d[fill[ur]++] = -d;
  }
  return s;
}

// y = L x for the weighted Laplacian (rows in parallel: each output is independent, so the result
// does not depend on the number of workers).
void laplacian(const ArcSystem& s, const LargeVector<double>& x, LargeVector<double>& y) {
  const std::size_t n = x.size();
  parallel_chunks(n, worker_count(n), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t f = b; f < e; ++f) {
      double sum = 0.0;
      for (int k = s.begin[f]; k < s.begin[f + 1]; ++k) sum += s.omega[k] * (x[f] - x[s.other[k]]);
      y[f] = sum;
    }
  });
}

}  // namespace

void solve_weights(const TracedGraph& t, const SolveOrder& order, LargeVector<FaceSite>& site) {
  const std::size_t n = order.order.size();
  const ArcSystem s = arc_system(t, order, site);
  if (s.other.empty()) return;
  LargeVector<double> u(n, 0.0), r(n, 0.0), q(n, 0.0), diag(n, 0.0);
  // The start: the ratios integrated again, from both sites of each arc after the position solve
  // (the propagated weights carry the propagated positions' rounding). In breadth-first order each
  // face takes its value across its most trusted arc (largest ω) to a face numbered before it: an
  // ill-conditioned arc would otherwise shift a whole subtree, an error the iteration removes
  // slowest.
  u[0] = std::log(site[order.order[0]].weight);
  for (std::size_t f = 1; f < n; ++f) {
    int best = kNone;
    for (int k = s.begin[f]; k < s.begin[f + 1]; ++k)
      if (s.other[k] < static_cast<int>(f) && (best == kNone || s.omega[k] > s.omega[best])) best = k;
    u[f] = best == kNone ? std::log(site[order.order[f]].weight) : u[s.other[best]] - s.d[best];
  }
  // Residual of the normal equations L u = b, b_f = -Σ ω d over f's arcs (d: u_other - u_f).
  laplacian(s, u, q);
  // The rounding of the residual itself (its terms are ~ω·(|d| + |u|)): no iteration gets below it.
  double rz_floor = 0.0;
  for (std::size_t f = 0; f < n; ++f) {
    double b = 0.0, size = 0.0;
    for (int k = s.begin[f]; k < s.begin[f + 1]; ++k) {
      b -= s.omega[k] * s.d[k], diag[f] += s.omega[k];
      size += s.omega[k] * (std::abs(s.d[k]) + std::abs(u[f]) + std::abs(u[s.other[k]]));
    }
    r[f] = b - q[f];
    if (diag[f] > 0) rz_floor += (kEps * size) * (kEps * size) / diag[f];
  }
  // The Laplacian's null space (one common factor of all weights): the residual's mean, rounding
  // only, is taken out so that the iteration does not chase it.
  double mean = 0.0, counted = 0.0;
  for (std::size_t f = 0; f < n; ++f)
    if (diag[f] > 0) mean += r[f], counted += 1.0;
  mean /= counted;
  for (std::size_t f = 0; f < n; ++f)
    if (diag[f] > 0) r[f] -= mean;
  conjugate_gradients([&](const LargeVector<double>& in, LargeVector<double>& out) { laplacian(s, in, out); }, diag, u, r,
                      rz_floor);
  for (std::size_t f = 0; f < n; ++f)
    if (!std::isfinite(u[f])) return;  // keep the propagated weights
  for (std::size_t f = 0; f < n; ++f) site[order.order[f]].weight = std::exp(u[f]);
}

}  // namespace covmap::recognition::stages
