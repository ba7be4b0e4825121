// Cycle orientation for trace_faces(): each closed cycle's signed area (outer cycles are
// counter-clockwise or pass through infinity, holes clockwise), and each half-arc's cycle.
#include "core/parallel.h"
#include "voronoi/face_tracing.h"

namespace covmap::voronoi::tracing {

LargeVector<int> orient_cycles(const Diagram& d, const TracingGeometry& geometry, CycleSet& cs) {
  LargeVector<Cycle>& cycles = cs.cycles;
  const LargeVector<int>& cycle_halves = cs.cycle_halves;
  LargeVector<int> cycle_of_half(2 * d.arcs.size(), -1);
  parallel_chunks(cycles.size(), worker_count(cycles.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t c = b; c < e; ++c) {
      Cycle& cyc = cycles[c];
      // Orientation by signed area: chords (shoelace about the first node, against cancellation
      // far from the origin) plus the circular segments between chords and arcs.
      const int origin_node = info(d, cycle_halves[cyc.begin]).start;
      const Point o = origin_node == kNone ? Point{0, 0} : Point{d.nodes[origin_node].x, d.nodes[origin_node].y};
      for (int k = cyc.begin; k < cyc.end; ++k) {
        const int h = cycle_halves[k];
        cycle_of_half[h] = static_cast<int>(c);
        const HalfInfo hi = info(d, h);
        cyc.area2 += (h % 2 == 0 ? 1.0 : -1.0) * geometry.segment_area2[h / 2];
        if (hi.start != kNone && hi.end != kNone) {
          const Node& a = d.nodes[hi.start];
          const Node& b = d.nodes[hi.end];
          cyc.area2 += (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y);
        }
        if (hi.end == kNone && std::holds_alternative<Line>(d.arcs[h / 2].curve)) cyc.through_infinity = true;
      }
    }
  });
  return cycle_of_half;
}

}  // namespace covmap::voronoi::tracing
