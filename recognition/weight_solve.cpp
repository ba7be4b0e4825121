// Weight solve in recognize(): the log-weights of all faces by weighted least squares over every
// arc. Each arc with sites s_l, s_r on its two sides states their weight ratio (Lemma 1:
// w_l / w_r = |c - s_l| / r = r / |c - s_r|, equal weights for a line); breadth-first propagation
// uses only the arcs of one spanning tree, so its weights carry the sum of the rounding along the
// tree path (~√depth crossings, growing with the graph). Here every arc
// counts: minimise Σ ω_a (u_r - u_l - d_a)² over u = log w, a graph-Laplacian system, started from
// the ratios integrated along the tree again from the refined sites and solved by conjugate
// gradients preconditioned with aggregation multigrid (laplacian_multigrid.h).
//
// Why multigrid: the Laplacian's condition grows like the number of faces, and Jacobi-preconditioned
// conjugate gradients need O(√n) iterations. Where the start is good that does not show, but one
// wrong statement (an arc the engine drew as a line between sites of slightly different weights)
// shifts the whole subtree behind it, and Jacobi stops at its iteration cap with weights off across
// the graph. Multigrid-preconditioned, the same system reaches its rounding and the solution a
// sparse direct factorisation gives, at a fraction of the factorisation's time and memory.
#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "core/parallel.h"
#include "mobius/bisector_relation.h"
#include "recognition/conjugate_gradients.h"
#include "recognition/laplacian_multigrid.h"
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

// log(w_r / w_l) from both sites, and how much the arc is trusted. Lemma 1 gives it twice, with the
// circle's stated radius r and the distances of its centre from the sites: log(r / |c - s_l|) and
// log(|c - s_r| / r) (relative to a node v of the arc, bisector_relation.h: |c - s| = |γ - δ|).
// Each is as accurate as its distance is long compared with the sites' (and centre's) absolute
// error σ: its variance is ~σ² / |c - s|². Weighting each by the inverse of its variance, the
// statement's variance is σ² / (|c - s_l|² + |c - s_r|²) and its weight in the least squares
// (|c - s_l|² + |c - s_r|²) over the graph's mean site spacing squared, between 1 and kMaxArcWeight.
// (An even average of both forms would let the short distance of a light site enclosed by a heavy
// one dominate, with several times the weight error.)
std::pair<double, double> arc_ratio(const Arc& arc, const std::vector<Node>& nodes, const mobius::ArcBisector& b,
                                    mobius::Complex sl, mobius::Complex sr, double spacing) {
  if (b.line) {
    // Equal weights, exactly for a line of equal-weight sites; but a writer may also put a line for
    // a short arc of a circle too flat to tell from its chord (the engine does, for radii beyond 10⁶
    // times the sites' spacing: weights equal only to 10⁻⁶), and one such segment among 10⁶ faces,
    // trusted as much as any line, set 2.4e-7 of weight error over the subtree behind it. A segment
    // is trusted as its length over the spacing, squared (a flat arc is short); a whole line or a
    // ray, fully.
    if (arc.from == kNone || arc.to == kNone) return {0.0, tolerance::kMaxArcWeight};
    const double chord = std::hypot(nodes[arc.to].x - nodes[arc.from].x, nodes[arc.to].y - nodes[arc.from].y);
    return {0.0, std::clamp(chord * chord / (spacing * spacing), 1.0, tolerance::kMaxArcWeight)};
  }
  const double r = std::get<Circle>(arc.curve).r;
  const double dl = std::abs(b.gamma - (sl - b.v)), dr = std::abs(b.gamma - (sr - b.v));
  const double trust_l = dl * dl, trust_r = dr * dr, trust = trust_l + trust_r;
  const double d = (trust_l * std::log(r / dl) + trust_r * std::log(dr / r)) / trust;
  return {d, std::clamp(trust / (spacing * spacing), 1.0, tolerance::kMaxArcWeight)};
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
  const double spacing = t.scale / std::sqrt(static_cast<double>(faces));
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    int l, r;
    if (!usable(a, l, r)) continue;
    const mobius::ArcBisector b = mobius::arc_bisector(g.arcs[a], g.nodes, site[l].position);
    auto [d, omega] = arc_ratio(g.arcs[a], g.nodes, b, site[l].position, site[r].position, spacing);
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

// The normal equations' matrix for a correction that is 0 at every anchor: the anchors' rows become
// identity rows (excess 1, no edges), and each other face keeps its arcs to non-anchors as edges and
// those to anchors as excess.
GroundedLaplacian grounded_system(const ArcSystem& s, const LargeVector<char>& anchor) {
  const std::size_t n = anchor.size();
  GroundedLaplacian a;
  a.begin.assign(n + 1, 0);
  a.excess.assign(n, 0.0);
  a.other.reserve(s.other.size());
  a.weight.reserve(s.other.size());
  for (std::size_t f = 0; f < n; ++f) {
    if (anchor[f]) {
      a.excess[f] = 1.0;
    } else {
      for (int k = s.begin[f]; k < s.begin[f + 1]; ++k) {
        if (!(s.omega[k] > 0)) continue;
        if (anchor[s.other[k]]) {
          a.excess[f] += s.omega[k];
        } else {
          a.other.push_back(s.other[k]);
          a.weight.push_back(s.omega[k]);
        }
      }
    }
    a.begin[f + 1] = static_cast<int>(a.other.size());
  }
  a.finish();
  return a;
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
  // ill-conditioned arc would otherwise shift a whole subtree. A face with no such arc is an anchor.
  LargeVector<char> anchor(n, 0);
  for (std::size_t f = 0; f < n; ++f) {
    int best = kNone;
    for (int k = s.begin[f]; k < s.begin[f + 1]; ++k)
      if (s.other[k] < static_cast<int>(f) && s.omega[k] > 0 && (best == kNone || s.omega[k] > s.omega[best])) best = k;
    anchor[f] = best == kNone;
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
  // The correction δ (u + δ solves the normal equations) with every anchor held: the grounded
  // Laplacian of the other faces. The anchors — the first face of each connected part, which took its
  // start from its own propagated weight — fix the one free factor per part. (rz_floor measures the
  // residual's rounding in the Jacobi norm; the multigrid's norm of that high-frequency noise is of
  // the same size.)
  const LaplacianMultigrid multigrid(grounded_system(s, anchor));
  LargeVector<double> delta(n, 0.0);
  for (std::size_t f = 0; f < n; ++f)
    if (anchor[f]) r[f] = 0.0;
  preconditioned_conjugate_gradients(
      [&](const LargeVector<double>& in, LargeVector<double>& out) { multigrid.matrix().apply(in, out); },
      [&](const LargeVector<double>& in, LargeVector<double>& out) { multigrid.precondition(in, out); }, delta, r,
      rz_floor, true);
  for (std::size_t f = 0; f < n; ++f) u[f] += delta[f];
  for (std::size_t f = 0; f < n; ++f)
    if (!std::isfinite(u[f])) return;  // keep the propagated weights
  for (std::size_t f = 0; f < n; ++f) site[order.order[f]].weight = std::exp(u[f]);
}

}  // namespace covmap::recognition::stages
