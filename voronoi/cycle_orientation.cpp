// Cycle orientation for trace_faces(): each closed cycle's signed area (outer cycles are
// counter-clockwise or pass through infinity, holes clockwise), and each half-arc's cycle.
#include <cmath>
#include <limits>
#include <span>

#include "core/arc_sweep.h"
#include "core/parallel.h"
#include "voronoi/face_tracing.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi::tracing {

namespace {

// Twice the signed area of the triangle (o, a, b) of half-arc h's chord from node a to node b.
// For a segment it is read from the line's own stated point q and unit direction u as
// ((b - a)·u) · cross(q - o, u), equal to cross(a - o, b - o) for nodes on their line: a segment
// between two nodes 1e14 and 5e14 out (nearly collinear sites) rounds its nodes by 0.06, more than
// the strip it bounds is wide, and the cross product of the rounded nodes lost the sign of the
// whole cycle; the line's point near the graph and its direction keep it.
double chord_area2(const Diagram& d, int h, const HalfInfo& hi, Point o) {
  const Node& a = d.nodes[hi.start];
  const Node& b = d.nodes[hi.end];
  if (const Line* l = std::get_if<Line>(&d.arcs[h / 2].curve)) {
    const double len = std::hypot(l->dx, l->dy);
    if (len > 0) {
      const double ux = l->dx / len, uy = l->dy / len;
      return ((b.x - a.x) * ux + (b.y - a.y) * uy) * ((l->x - o.x) * uy - (l->y - o.y) * ux);
    }
  }
  return (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y);
}

// A closed cycle's total turning, 2π for a counter-clockwise simple cycle and -2π for a clockwise
// one: each circle arc's signed sweep, and at each node the turn π - δ, δ the counter-clockwise
// angle from the next departure to the reversed arrival. The continuation at a node is the
// departure just clockwise of the reversed arrival, so when the two leave in one direction
// (tangent arcs) δ is 0 and the turn π. Directions only, no areas: it decides cycles whose area is
// below the rounding of their nodes (a lens of a circle and its near-tangent line between nodes an
// ulp apart, in a grid at k/25 scaled by 1e-3).
double total_turning(const Diagram& d, std::span<const int> halves) {
  double total = 0.0;
  for (std::size_t k = 0; k < halves.size(); ++k) {
    const int h = halves[k], n = halves[(k + 1) % halves.size()];
    const Arc& arc = d.arcs[h / 2];
    const bool forward = h % 2 == 0;
    if (const Circle* c = std::get_if<Circle>(&arc.curve)) {
      const double sweep = circle_arc_sweep(arc, *c, d.nodes).sweep;
      total += arc.ccw == forward ? sweep : -sweep;
    }
    const int end = forward ? arc.to : arc.from;
    if (end == kNone) {
      if (halves.size() == 1) continue;  // a full circle
      return std::numeric_limits<double>::quiet_NaN();
    }
    const Arc& next = d.arcs[n / 2];
    const Point back = departure_vector(arc, d.nodes[end], !forward);
    const Point out = departure_vector(next, d.nodes[n % 2 == 0 ? next.from : next.to], n % 2 == 0);
    double delta = wrap_angle(std::atan2(out.x * back.y - out.y * back.x, out.x * back.x + out.y * back.y));
    if (delta < tolerance::kParallelAngle || delta > kTwoPi - tolerance::kParallelAngle) delta = 0.0;
    total += M_PI - delta;
  }
  return total;
}

}  // namespace

LargeVector<int> orient_cycles(const Diagram& d, const TracingGeometry& geometry, CycleSet& cs) {
  LargeVector<Cycle>& cycles = cs.cycles;
  const LargeVector<int>& cycle_halves = cs.cycle_halves;
  LargeVector<int> cycle_of_half(2 * d.arcs.size(), -1);
  parallel_chunks(cycles.size(), worker_count(cycles.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t c = b; c < e; ++c) {
      Cycle& cyc = cycles[c];
      // Orientation by signed area: chords (shoelace about one of the cycle's nodes, against
      // cancellation far from the origin) plus the circular segments between chords and arcs. The
      // node is the one of least magnitude: about a node 1e15 out (nearly collinear sites put
      // several there) every chord term is ~1e30 and the thin wedges of such a cycle, ~1e13 in
      // area, lost their sign; about a node near the others each term is only as large as the
      // cycle's true extent allows.
      Point o{0, 0};
      double least = INFINITY;
      for (int k = cyc.begin; k < cyc.end; ++k) {
        const int v = info(d, cycle_halves[k]).start;
        if (v == kNone) continue;
        const double magnitude = std::fabs(d.nodes[v].x) + std::fabs(d.nodes[v].y);
        if (magnitude < least) least = magnitude, o = {d.nodes[v].x, d.nodes[v].y};
      }
      double magnitude = 0.0;  // of the terms summed: the area's rounding is a few ulps of it
      for (int k = cyc.begin; k < cyc.end; ++k) {
        const int h = cycle_halves[k];
        cycle_of_half[h] = static_cast<int>(c);
        const HalfInfo hi = info(d, h);
        const double segment = (h % 2 == 0 ? 1.0 : -1.0) * geometry.segment_area2[h / 2];
        const double chord = hi.start != kNone && hi.end != kNone ? chord_area2(d, h, hi, o) : 0.0;
        cyc.area2 += segment + chord;
        magnitude += std::fabs(segment) + std::fabs(chord);
        if (hi.end == kNone && std::holds_alternative<Line>(d.arcs[h / 2].curve)) cyc.through_infinity = true;
      }
      // An area within rounding of 0 has no sign to trust: the cycle's turning gives it.
      if (!cyc.through_infinity &&
          std::fabs(cyc.area2) <= tolerance::kOrientationAreaUlps * std::numeric_limits<double>::epsilon() * magnitude) {
        const double turning = total_turning(d, cs.halves_of(cyc));
        if (std::isfinite(turning) && std::fabs(turning) > M_PI)
          cyc.area2 = std::copysign(std::max(std::fabs(cyc.area2), std::numeric_limits<double>::min()), turning);
      }
    }
  });
  return cycle_of_half;
}

}  // namespace covmap::voronoi::tracing
