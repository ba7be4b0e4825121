// Node constraints in recognize(): going once around a node, across every arc there and back,
// fixes the site of the face one starts from (Lemma 5, §4.4; mobius/node_constraint.h). Here: the
// walk around the node through the traced faces, and the exact reading of the fixed set.
#include <algorithm>
#include <cmath>
#include <array>
#include <span>
#include <vector>

#include "mobius/node_constraint.h"
#include "recognition/recognize_stages.h"
#include "recognition/tolerances.h"

namespace covmap::recognition::stages {

double matrix_tolerance(const TracedGraph& t, mobius::Complex v, double L) {
  return std::clamp(t.tol_at(v) / L, tolerance::kMatrixRounding, tolerance::kMatrixCeiling);
}

// Composed in the node's own frame z' = (z - v) / L, where every arc at v passes through the
// origin and has a normalised form: an arc of a huge circle (nearly equal weights) is then a
// near-reflection with O(1) matrix entries, where in plane coordinates its inversion matrix has
// entries ~R² that cancel in the composition (the solution circle would lose ~(R/L)² digits).
std::optional<Constraint> node_constraint(const TracedGraph& t, int f, int h_out) {
  const Diagram& g = t.g;
  const LargeVector<int>& face_of_half = t.face_of_half;
  const LargeVector<int>& next_half = t.next_half;
  const double scale = t.scale;
  const Arc& first = g.arcs[h_out / 2];
  const int v = (h_out % 2 == 0) ? first.from : first.to;
  const mobius::Complex at(g.nodes[v].x, g.nodes[v].y);
  // The half-arcs of the walk around v, and the neighbourhood's size: the median reach of the arcs
  // at v to their other ends. Not the first arc's: a node of degree four split by a perturbation of
  // 1e-15 has a tiny arc, and in a frame that small the sites sit 1e13 units out, where a solution
  // circle of ordinary size reads as its tangent line (grids moved by 1e-15 would be rejected). Not
  // the longest: an arc of nearly equal weights may run 1e6 out, and the lines the engine writes
  // for such flat circles make the composition an involution only to ~L/r, which in so large a
  // frame exceeded the tolerance (weights equal to 1e-9: a solution circle read as two points).
  // Fixed capacity, no allocation: every node of every face is walked when a graph is rejected
  // (disagreeing_node.cpp), and no node of a bisector graph needs more than kMaxWalk arcs here.
  constexpr std::size_t kMaxWalk = 64;
  std::array<int, kMaxWalk> walk_buffer;
  std::array<double, kMaxWalk> reach_buffer;
  std::size_t walked = 0, reached = 0;
  for (int h = h_out, face = f;;) {
    if (h == kNone || g.arcs[h / 2].frame || walked >= kMaxWalk) return std::nullopt;
    walk_buffer[walked++] = h;
    const Arc& arc = g.arcs[h / 2];
    const int far_end = (h % 2 == 0) ? arc.to : arc.from;
    if (far_end != kNone) reach_buffer[reached++] = std::abs(mobius::Complex(g.nodes[far_end].x, g.nodes[far_end].y) - at);
    const int twin = h ^ 1;
    face = face_of_half[twin];
    h = next_half[twin];
    if (face == f && h == h_out) break;
  }
  // No more than the node's distance from the graph (where the sites are) plus the graph's scale:
  // an arc of nearly equal weights may run from a node inside the graph to one 1e10 out, and in a
  // frame that large the graph sits within 1e-8 of the origin, where the matrix tolerance falls to
  // rounding and a solution circle reads as two points.
  const double reach = scale + t.extent.distance_to({at.real(), at.imag()});
  // Arcs shorter than kNodeFrameFloor of the graph (the rest of a node split by rounding: a grid
  // in decimal coordinates splits a point of five sites into three nodes an ulp apart) say
  // nothing about where the sites are.
  const double floor = tolerance::kNodeFrameFloor * scale;
  double L = 0.0;
  const std::span<double> reaches(reach_buffer.data(), reached);
  const auto tiny = std::partition(reaches.begin(), reaches.end(), [&](double r) { return r >= floor; });
  if (tiny == reaches.begin() && !reaches.empty()) {
    L = *std::max_element(reaches.begin(), reaches.end());
  } else if (tiny != reaches.begin()) {
    const auto middle = reaches.begin() + (tiny - reaches.begin()) / 2;
    std::nth_element(reaches.begin(), middle, tiny);
    L = *middle;
  }
  if (!(L > 0) || L > reach) L = reach;
  const mobius::NodeFrame frame{at, L};
  const double mt = matrix_tolerance(t, at, L);
  mobius::Mobius h_total;
  for (const int h : std::span<const int>(walk_buffer.data(), walked)) h_total = mobius::then_invert_in(h_total, g.arcs[h / 2], frame);
  Constraint c;
  static_cast<mobius::NodeConstraint&>(c) = mobius::exact_fixed_set(h_total, mt);
  // A solution circle through the node whose curvature is at the rounding of the composition
  // (radius beyond L / kSolutionLine) is its tangent line (A exactly 0), so that a rounding-level A
  // does not become a circle of radius 1e16 in plane coordinates. (Not mt: a curvature within a
  // rounded graph's noise is still a circle — taking it as a line would move the site, which may
  // lie many L away, by far more than that noise.)
  if (c.is_circle && std::abs(c.circle.A) <= tolerance::kSolutionLine * std::abs(c.circle.B)) c.circle.A = 0.0;
  if (c.is_circle) c.circle = frame.to_plane(c.circle);
  for (mobius::Complex& p : c.points) p = frame.to_plane(p);
  return c;
}

}  // namespace covmap::recognition::stages
