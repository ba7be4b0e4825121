// Cycle orientation for trace_faces(): each closed cycle's signed area (outer cycles are
// counter-clockwise or pass through infinity, holes clockwise), and each half-arc's cycle.
#include <cmath>

#include "core/parallel.h"
#include "voronoi/face_tracing.h"

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
      for (int k = cyc.begin; k < cyc.end; ++k) {
        const int h = cycle_halves[k];
        cycle_of_half[h] = static_cast<int>(c);
        const HalfInfo hi = info(d, h);
        cyc.area2 += (h % 2 == 0 ? 1.0 : -1.0) * geometry.segment_area2[h / 2];
        if (hi.start != kNone && hi.end != kNone) cyc.area2 += chord_area2(d, h, hi, o);
        if (hi.end == kNone && std::holds_alternative<Line>(d.arcs[h / 2].curve)) cyc.through_infinity = true;
      }
    }
  });
  return cycle_of_half;
}

}  // namespace covmap::voronoi::tracing
