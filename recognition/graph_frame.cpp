// The graph frame of recognize(): the graph centred and scaled before any geometry is done, and the
// answer mapped back. Recognition is then the same whether a graph sits at the origin or near 1e7,
// and whatever its size: every generalized-circle form, solution circle and candidate is formed in
// coordinates of size ~1.
#include <cmath>
#include <utility>
#include <variant>

#include "core/parallel.h"
#include "recognition/recognize_stages.h"
#include "recognition/tolerances.h"

namespace covmap::recognition::stages {
namespace {

void map_nodes_and_curves(Diagram& g, mobius::Complex origin, double scale_by) {
  parallel_chunks(g.nodes.size(), worker_count(g.nodes.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t v = b; v < e; ++v) {
      g.nodes[v].x = (g.nodes[v].x - origin.real()) * scale_by;
      g.nodes[v].y = (g.nodes[v].y - origin.imag()) * scale_by;
    }
  });
  parallel_chunks(g.arcs.size(), worker_count(g.arcs.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t a = b; a < e; ++a) {
      if (auto* c = std::get_if<Circle>(&g.arcs[a].curve)) {
        c->cx = (c->cx - origin.real()) * scale_by;
        c->cy = (c->cy - origin.imag()) * scale_by;
        c->r *= scale_by;
      } else {
        auto& l = std::get<Line>(g.arcs[a].curve);
        l.x = (l.x - origin.real()) * scale_by;
        l.y = (l.y - origin.imag()) * scale_by;
      }
    }
  });
}

mobius::Complex point_to_plane(const GraphFrame& f, double& x, double& y) {
  const mobius::Complex p = f.NodeFrame::to_plane(mobius::Complex(x, y));
  x = p.real(), y = p.imag();
  return p;
}

}  // namespace

GraphFrame graph_frame(const Box& extent, double scale) {
  GraphFrame f;
  const mobius::Complex middle(extent.centre().x, extent.centre().y);
  // Near the origin (within a few extents) a translation would gain nothing and lose exactness.
  if (std::abs(middle) > tolerance::kFrameTranslation * scale) {
    f.origin = middle;
    f.translated = true;
  }
  f.unit = std::ldexp(1.0, std::ilogb(scale));  // a power of two: scaling is exact both ways
  return f;
}

SavedGeometry to_frame(Diagram& g, const GraphFrame& frame) {
  SavedGeometry saved;
  if (frame.translated) {
    saved.nodes.assign(g.nodes.begin(), g.nodes.end());
    saved.curves.reserve(g.arcs.size());
    for (const Arc& a : g.arcs) saved.curves.push_back(a.curve);
  }
  map_nodes_and_curves(g, frame.origin, 1.0 / frame.unit);
  return saved;
}

void to_plane(Diagram& g, const GraphFrame& frame, SavedGeometry& saved) {
  if (!frame.translated) {
    map_nodes_and_curves(g, {0.0, 0.0}, frame.unit);
    return;
  }
  std::copy(saved.nodes.begin(), saved.nodes.end(), g.nodes.begin());
  for (std::size_t a = 0; a < g.arcs.size(); ++a) g.arcs[a].curve = std::move(saved.curves[a]);
  saved = SavedGeometry{};
}

InputScale scale_in_frame(const InputScale& in, const GraphFrame& frame) {
  InputScale out = in;
  const mobius::Complex lo = frame.to_frame({in.extent.xmin, in.extent.ymin});
  const mobius::Complex hi = frame.to_frame({in.extent.xmax, in.extent.ymax});
  out.extent = Box{lo.real(), lo.imag(), hi.real(), hi.imag()};
  out.scale = in.scale / frame.unit;
  out.tol = in.tol / frame.unit;
  return out;
}

void to_plane(Reconstruction& r, const GraphFrame& frame) {
  for (Site& s : r.sites) point_to_plane(frame, s.x, s.y);
  for (auto& candidate : r.candidates)
    for (Site& s : candidate) point_to_plane(frame, s.x, s.y);
  if (r.region) {
    for (auto& b : r.region->bounds) b = frame.NodeFrame::to_plane(b);
    point_to_plane(frame, r.region->representative.x, r.region->representative.y);
    r.region->margin *= frame.unit;
  }
  auto residual_to_plane = [&](Residual& x) {
    point_to_plane(frame, x.x, x.y);
    x.amount *= frame.unit;
    x.allowed *= frame.unit;
  };
  for (Residual& x : r.residuals.worst) residual_to_plane(x);
  r.residuals.tolerance *= frame.unit;
  if (r.failure) {
    point_to_plane(frame, r.failure->x, r.failure->y);
    r.failure->amount *= frame.unit;
  }
}

}  // namespace covmap::recognition::stages
