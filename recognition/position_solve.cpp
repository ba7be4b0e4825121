// Position solve in recognize(): the sites of all faces refined by least squares over every arc.
// Propagation fixes each site from its parent's across one arc of a spanning tree, so rounding
// adds up along the tree path; every arc, though, states that its two sites are mirror images in it
// (Lemma 1): s_r = M_a(s_l). One Gauss-Newton step on Σ_a |s_r - M_a(s_l)|² / |k_a|, with k_a the
// derivative of the inversion (δM = k_a conj(δs), |k_a| = (w_r / w_l)²: dividing by it makes the
// residual the same whichever way the arc is read), solved by Jacobi-preconditioned conjugate
// gradients from zero. The propagated sites are the linearisation point; the correction is of the
// size of their rounding (or, for rounded graphs, of the rounding of the graph).
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "mobius/bisector_relation.h"
#include "recognition/conjugate_gradients.h"
#include "recognition/recognize_stages.h"
#include "recognition/tolerances.h"

namespace covmap::recognition::stages {
namespace {

using mobius::Complex;

// a·b without the library's NaN-recovering complex product (a call per product, most of the cost
// of the iteration); operands here are finite.
inline Complex times(Complex a, Complex b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

// One arc's linearised statement: e + δs_r - k conj(δs_l) ≈ 0, scaled by 1/√|k| and by the
// accuracy of the arc's numbers.
struct ArcRow {
  int l = kNone, r = kNone;
  Complex e, k;
  double scale = 1.0;  // 1 / (√|k| · (1 + the arc's node's distance from the graph / extent))
};

LargeVector<ArcRow> arc_rows(const TracedGraph& t, const SolveOrder& order, const LargeVector<FaceSite>& site) {
  const Diagram& g = t.g;
  LargeVector<ArcRow> rows;
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    const int l = t.face_of_half[2 * a], r = t.face_of_half[2 * a + 1];
    if (g.arcs[a].frame || l == kNone || r == kNone || l == r || order.rank[l] == kNone || order.rank[r] == kNone) continue;
    const Complex sl = site[l].position;
    const mobius::ArcBisector b = mobius::arc_bisector(g.arcs[a], g.nodes, sl);
    ArcRow row{order.rank[l], order.rank[r], {}, {}, 1.0};
    row.e = site[r].position - mobius::partner_across(b, {sl, 1.0}).position;
    if (b.line) {
      row.k = b.gamma * b.gamma;  // reflection in a line of unit direction γ: δM = γ² conj(δs)
    } else {
      const Complex away = std::conj(sl - b.v - b.gamma);  // conj(δ - γ)
      row.k = -std::norm(b.gamma) / (away * away);
    }
    const double modulus = std::abs(row.k);
    if (!(modulus > 0) || !std::isfinite(modulus) || !std::isfinite(std::abs(row.e))) continue;
    // An arc through a far node is stated only to its distance's rounding (verification.cpp): its
    // residual counts in proportion to that accuracy, so that it does not pull the nearby sites.
    const double far = 1.0 + t.extent.distance_to({b.v.real(), b.v.imag()}) / t.scale;
    row.scale = 1.0 / (std::sqrt(modulus) * far);
    rows.push_back(row);
  }
  // In the order of their left faces' unknowns: the gather per face then reads half its rows'
  // values in sequence (memory-bound at 10^5 faces and more).
  std::sort(rows.begin(), rows.end(), [](const ArcRow& a, const ArcRow& b) { return a.l < b.l || (a.l == b.l && a.r < b.r); });
  return rows;
}

// y = Jᵀ J x, the rows gathered per face (arcs scattered to their two faces through per-face
// lists, so that each output is summed in a fixed order whatever the number of workers).
struct NormalOperator {
  const LargeVector<ArcRow>& rows;
  LargeVector<int> begin, entry;  // per face: the rows it takes part in (entry = 2·row + side)
  LargeVector<Complex> coef;      // per entry: the row's coefficient of that face (side r: scale; l: -scale·k)

  NormalOperator(const LargeVector<ArcRow>& rs, std::size_t faces) : rows(rs) {
    begin.assign(faces + 1, 0);
    for (const ArcRow& row : rows) ++begin[row.l + 1], ++begin[row.r + 1];
    for (std::size_t f = 0; f < faces; ++f) begin[f + 1] += begin[f];
    entry.resize(begin[faces]);
    coef.resize(begin[faces]);
    LargeVector<int> fill(begin.begin(), begin.end() - 1);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      coef[fill[rows[k].l]] = -rows[k].scale * rows[k].k;
      entry[fill[rows[k].l]++] = static_cast<int>(2 * k);
      coef[fill[rows[k].r]] = rows[k].scale;
      entry[fill[rows[k].r]++] = static_cast<int>(2 * k + 1);
    }
  }
  // The rows' values J x first (one pass over the arcs), then gathered per face (Jᵀ).
  void apply(const LargeVector<Complex>& x, LargeVector<Complex>& y) const {
    values.resize(rows.size());
    parallel_chunks(rows.size(), worker_count(rows.size()), [&](std::size_t b, std::size_t e, int) {
      for (std::size_t k = b; k < e; ++k) {
        const ArcRow& row = rows[k];
        values[k] = row.scale * (x[row.r] - times(row.k, std::conj(x[row.l])));
      }
    });
    const std::size_t n = x.size();
    parallel_chunks(n, worker_count(n), [&](std::size_t b, std::size_t e, int) {
      for (std::size_t f = b; f < e; ++f) {
        Complex sum = 0.0;
        for (int k = begin[f]; k < begin[f + 1]; ++k) {
          const Complex v = values[entry[k] / 2];
          sum += times(coef[k], (entry[k] % 2 == 1) ? v : std::conj(v));
        }
        y[f] = sum;
      }
    });
  }
  mutable LargeVector<Complex> values;  // per row: J x
};

// One Gauss-Newton step; the largest correction made (0 when none was made).
double gauss_newton_step(const TracedGraph& t, const SolveOrder& order, LargeVector<FaceSite>& site) {
  const std::size_t n = order.order.size();
  const LargeVector<ArcRow> rows = arc_rows(t, order, site);
  if (rows.empty()) return 0.0;
  const NormalOperator op(rows, n);
  // Right-hand side -Jᵀ e (the residual at x = 0), and the Jacobi preconditioner (each face's
  // block is a multiple of 1).
  LargeVector<Complex> r(n, 0.0), x(n, 0.0);
  LargeVector<double> diag(n, 0.0);
  for (const ArcRow& row : rows) {
    const Complex v = row.scale * row.e;
    r[row.r] -= row.scale * v;
    r[row.l] += row.scale * row.k * std::conj(v);
    diag[row.r] += row.scale * row.scale;
    diag[row.l] += row.scale * row.scale * std::norm(row.k);
  }
  conjugate_gradients([&](const LargeVector<Complex>& in, LargeVector<Complex>& out) { op.apply(in, out); }, diag, x, r);
  // A correction comparable with the graph is no refinement: the linearisation would not hold.
  double largest = 0.0;
  for (std::size_t f = 0; f < n; ++f) {
    if (!std::isfinite(std::abs(x[f])) || std::abs(x[f]) > tolerance::kLinearisation * t.scale) return 0.0;
    largest = std::max(largest, std::abs(x[f]));
  }
  for (std::size_t f = 0; f < n; ++f) site[order.order[f]].position += x[f];
  return largest;
}

}  // namespace

SolveOrder::SolveOrder(const LargeVector<int>& faces_in_order, std::size_t faces) : order(faces_in_order) {
  rank.assign(faces, kNone);
  for (std::size_t k = 0; k < order.size(); ++k) rank[order[k]] = static_cast<int>(k);
}

void solve_positions(const TracedGraph& t, const SolveOrder& order, LargeVector<FaceSite>& site) {
  for (int step = 0; step < tolerance::kPositionSteps; ++step)
    if (!(gauss_newton_step(t, order, site) > tolerance::kFurtherStep * t.scale)) break;
}

}  // namespace covmap::recognition::stages
