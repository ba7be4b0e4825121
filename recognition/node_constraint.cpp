// Node constraints in recognize(): going once around a node, across every arc there and back,
// fixes the site of the face one starts from (Lemma 5, §4.4).
#include <algorithm>
#include <cmath>

#include "mobius/mobius.h"
#include "mobius/node_frame.h"
#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {

namespace {

// The fixed set of the composed map around a node, in the node's frame: a circle, at most two
// points, or (the identity) no constraint.
Constraint fixed_set(const mobius::Mobius& h_total, double matrix_tolerance) {
  const double norm = std::max({std::abs(h_total.a()), std::abs(h_total.b()),
                                std::abs(h_total.c()), std::abs(h_total.d())});
  const double mt = matrix_tolerance * norm;
  Constraint c;
  if (h_total.conjugated()) {
    const auto forms = h_total.fixed_set_forms();
    auto size = [](const mobius::GeneralizedCircle& x) { return std::abs(x.A) + std::abs(x.B) + std::abs(x.C); };
    const double n0 = size(forms[0]), n1 = size(forms[1]);
    const mobius::GeneralizedCircle& big = n0 >= n1 ? forms[0] : forms[1];
    const mobius::GeneralizedCircle& small = n0 >= n1 ? forms[1] : forms[0];
    const double ratio = std::min(n0, n1) / std::max(n0, n1);
    // Proportional forms (or a vanishing one) describe one circle.
    const double lambda = (small.A * big.A + std::real(std::conj(small.B) * big.B) + small.C * big.C) /
                          (big.A * big.A + std::norm(big.B) + big.C * big.C);
    const double residual = std::abs(small.A - lambda * big.A) + std::abs(small.B - lambda * big.B) +
                            std::abs(small.C - lambda * big.C);
    if (ratio < matrix_tolerance || residual <= matrix_tolerance * std::max(n0, n1)) {
      c.is_circle = true;
      c.circle = big;
    } else {
      c.points = intersect(forms[0], forms[1]);
      if (c.points.empty()) {
        const auto c0 = forms[0].centre(), c1 = forms[1].centre();
        const auto r0 = forms[0].radius(), r1 = forms[1].radius();
        if (c0 && c1 && r0 && r1) {
          const double between = std::abs(*c0 - *c1);
          c.gap = std::max(between - *r0 - *r1, std::abs(*r0 - *r1) - between);
        } else {
          c.gap = INFINITY;  // an imaginary circle or parallel lines: no point at all
        }
      }
    }
  } else {
    const mobius::Complex a = h_total.a(), b = h_total.b(), cc = h_total.c(), d = h_total.d();
    if (std::abs(b) <= mt && std::abs(cc) <= mt && std::abs(a - d) <= mt) {
      c.any = true;  // the identity: this node constrains nothing
    } else if (std::abs(cc) <= mt) {
      if (std::abs(d - a) > mt) c.points.push_back(b / (d - a));
    } else {
      // c z² + (d - a) z - b = 0
      const mobius::Complex disc = std::sqrt((d - a) * (d - a) + 4.0 * cc * b);
      c.points.push_back((-(d - a) + disc) / (2.0 * cc));
      c.points.push_back((-(d - a) - disc) / (2.0 * cc));
    }
  }
  return c;
}

}  // namespace

// Composed in the node's own frame z' = (z - v) / L, where every arc at v passes through the
// origin and has a normalised form: an arc of a huge circle (nearly equal weights) is then a
// near-reflection with O(1) matrix entries, where in plane coordinates its inversion matrix has
// entries ~R² that cancel in the composition (the solution circle would lose ~(R/L)² digits).
std::optional<Constraint> node_constraint(const TracedGraph& t, double matrix_tolerance, int f, int h_out) {
  const Diagram& g = t.g;
  const LargeVector<int>& face_of_half = t.face_of_half;
  const LargeVector<int>& next_half = t.next_half;
  const double scale = t.scale;
  const Arc& first = g.arcs[h_out / 2];
  const int v = (h_out % 2 == 0) ? first.from : first.to;
  const mobius::Complex at(g.nodes[v].x, g.nodes[v].y);
  const int far_end = (h_out % 2 == 0) ? first.to : first.from;
  double L = far_end != kNone ? std::abs(mobius::Complex(g.nodes[far_end].x, g.nodes[far_end].y) - at) : 0.0;
  if (!(L > 0)) L = scale;
  mobius::Mobius h_total;
  int h = h_out, face = f, steps = 0;
  do {
    if (h == kNone || g.arcs[h / 2].frame) return std::nullopt;
    h_total = mobius::Mobius::inversion(mobius::curve_through_origin(g.arcs[h / 2], at, L)).after(h_total);
    const int twin = h ^ 1;
    face = face_of_half[twin];
    h = next_half[twin];
    if (++steps > 64) return std::nullopt;
  } while (face != f || h != h_out);
  Constraint c = fixed_set(h_total, matrix_tolerance);
  // Back to the plane.
  const mobius::Mobius to_plane(mobius::Complex(L, 0.0), at, mobius::Complex(0.0, 0.0), mobius::Complex(1.0, 0.0), false);
  // A solution circle through the node whose radius exceeds L / matrix_tolerance is its tangent
  // line to within the tolerance over the node's neighbourhood: a line (A exactly 0), so that a
  // rounding-level A does not become a circle of radius 1e16 in plane coordinates.
  if (c.is_circle && std::abs(c.circle.A) <= matrix_tolerance * std::abs(c.circle.B)) c.circle.A = 0.0;
  if (c.is_circle) c.circle = to_plane.apply(c.circle);
  for (mobius::Complex& p : c.points) p = at + L * p;
  return c;
}

// The solution circles of the nodes of face f (at most four), for re-anchoring the sites of faces
// at degenerate nodes (FaceIndex::degenerate_node: rounding of the sites decides their
// combinatorics, and re-anchoring on the nodes' solution circles lets the recomputed diagram
// reproduce them).
std::vector<Constraint> face_circle_constraints(const TracedGraph& t, double matrix_tolerance, int f) {
  const Diagram& g = t.g;
  std::vector<Constraint> cs;
  std::vector<int> seen_nodes;
  for (const auto& cycle : g.faces[f].boundaries)
    for (const HalfArc& hh : cycle) {
      const Arc& arc = g.arcs[hh.arc];
      const int v = hh.forward ? arc.from : arc.to;
      if (v == kNone || t.on_frame[v] || arc.frame) continue;
      if (std::find(seen_nodes.begin(), seen_nodes.end(), v) != seen_nodes.end()) continue;
      seen_nodes.push_back(v);
      if (auto c = node_constraint(t, matrix_tolerance, f, half_id(hh)); c && c->is_circle) cs.push_back(*c);
      if (cs.size() >= 4) return cs;
    }
  return cs;
}

}  // namespace covmap::recognition::stages
