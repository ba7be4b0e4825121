// Per-arc geometry for trace_faces(): departure directions and curvatures of the half-arcs,
// segment areas of the arcs, single-precision boxes; and the central box of the nodes.
#include <algorithm>
#include <cmath>

#include "core/arc_sweep.h"
#include "core/extent.h"
#include "core/parallel.h"
#include "voronoi/arc_path.h"
#include "voronoi/face_tracing.h"

namespace covmap::voronoi::tracing {
namespace {

FloatBox to_float_outward(const Box& b) {
  auto down = [](double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -INFINITY) : f;
  };
  auto up = [](double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, INFINITY) : f;
  };
  return {down(b.xmin), down(b.ymin), up(b.xmax), up(b.ymax)};
}

}  // namespace

// The arcs' end nodes are read here once for everything that needs them (they are scattered in
// memory: each read is a cache miss at 10^6 faces).
TracingGeometry tracing_geometry(const Diagram& d, bool with_boxes) {
  const std::size_t arcs = d.arcs.size();
  TracingGeometry g;
  g.depart.assign(2 * arcs, {});
  g.segment_area2.assign(arcs, 0.0);
  if (with_boxes) g.box.resize(arcs);
  // Independent per arc: shared by the workers (core/parallel.h).
  parallel_chunks(arcs, worker_count(arcs), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t a = b; a < e; ++a) {
      const Arc& arc = d.arcs[a];
      const Node none{};
      const Node& from = arc.from == kNone ? none : d.nodes[arc.from];
      const Node& to = arc.to == kNone ? none : d.nodes[arc.to];
      if (with_boxes) g.box[a] = to_float_outward(arc_bounds(arc, from, to));
      if (const Circle* c = std::get_if<Circle>(&arc.curve)) {
        const double sense = arc.ccw ? 1.0 : -1.0;
        if (arc.from != kNone) {
          const Point f = departure_vector(arc, from, true), b = departure_vector(arc, to, false);
          g.depart[2 * a] = {pseudo_angle(f.x, f.y), sense / c->r};
          g.depart[2 * a + 1] = {pseudo_angle(b.x, b.y), -sense / c->r};
        }
        // The extent as every reader of arcs sees it (core/arc_sweep.h: the same swept_angle).
        double sweep = kTwoPi;
        if (arc.from != kNone && arc.from != arc.to)
          sweep = swept_angle(from.x - c->cx, from.y - c->cy, to.x - c->cx, to.y - c->cy, arc.ccw);
        g.segment_area2[a] = sense * c->r * c->r * (sweep - std::sin(sweep));
      } else {
        const Line& l = std::get<Line>(arc.curve);
        if (arc.from != kNone) g.depart[2 * a].angle = pseudo_angle(l.dx, l.dy);
        if (arc.to != kNone) g.depart[2 * a + 1].angle = pseudo_angle(-l.dx, -l.dy);
      }
    }
  });
  return g;
}

// Only grid bounds depend on it (boxes outside land in the border cells), so a regular sample of at
// most 2^16 nodes stands in for all of them.
Box central_box(const std::vector<Node>& nodes) {
  LargeVector<double> xs, ys;
  const std::size_t stride = std::max<std::size_t>(1, nodes.size() >> 16);
  for (std::size_t k = 0; k < nodes.size(); k += stride) {
    const Node& n = nodes[k];
    if (std::isfinite(n.x) && std::isfinite(n.y)) xs.push_back(n.x), ys.push_back(n.y);
  }
  if (xs.empty()) return Box{};
  return central_extent(std::move(xs), std::move(ys));
}

}  // namespace covmap::voronoi::tracing
