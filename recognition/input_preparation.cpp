// Input preparation for recognize(): the input's labels taken off, its scale and tolerance, and the
// rejection of arcs whose end nodes are not on their curves.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/extent.h"
#include "core/parallel.h"
#include "recognition/recognize_stages.h"
#include "recognition/tolerances.h"

namespace covmap::recognition::stages {
namespace {

// The first arc end (in arc order) farther than `tol` plus rounding from its arc's curve.
struct EndOffCurve {
  int arc = kNone;
  int node = kNone;
  double distance = 0.0;
};
std::optional<EndOffCurve> first_end_off_curve(const Diagram& g, double tol) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  auto scan = [&](std::size_t begin, std::size_t end) -> std::optional<EndOffCurve> {
    for (std::size_t a = begin; a < end; ++a) {
      const Arc& arc = g.arcs[a];
      for (int v : {arc.from, arc.to}) {
        if (v == kNone) continue;
        const double x = g.nodes[v].x, y = g.nodes[v].y;
        double off = 0.0, rounding = 0.0;
        if (const auto* c = std::get_if<Circle>(&arc.curve)) {
          off = std::abs(std::sqrt((x - c->cx) * (x - c->cx) + (y - c->cy) * (y - c->cy)) - c->r);
          rounding = std::abs(c->cx) + std::abs(c->cy) + c->r;
        } else {
          const auto& l = std::get<Line>(arc.curve);
          off = std::abs((x - l.x) * l.dy - (y - l.y) * l.dx) / std::sqrt(l.dx * l.dx + l.dy * l.dy);
          rounding = std::abs(l.x) + std::abs(l.y);
        }
        rounding = tolerance::kArcEndRoundingUlps * eps * (rounding + std::abs(x) + std::abs(y));
        if (!(off <= tol + rounding)) return EndOffCurve{static_cast<int>(a), v, off};
      }
    }
    return std::nullopt;
  };
  const int workers = worker_count(g.arcs.size());
  std::vector<std::optional<EndOffCurve>> found(workers);
  parallel_chunks(g.arcs.size(), workers, [&](std::size_t b, std::size_t e, int w) { found[w] = scan(b, e); });
  for (const auto& f : found)
    if (f) return f;  // chunks are in arc order: the first found is the first arc
  return std::nullopt;
}

}  // namespace

InputScale prepare_input(Diagram& g, const RecognitionOptions& options) {
  g.sites.clear();
  clear_faces(g);
  InputScale in;
  // Frame arcs (a clipped map's boundary) are no bisectors: they bound faces but constrain no site.
  for (const Arc& a : g.arcs)
    if (a.frame) {
      in.clipped = true;
      break;
    }
  parallel_chunks(g.arcs.size(), worker_count(g.arcs.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t a = b; a < e; ++a) g.arcs[a].left_site = g.arcs[a].right_site = kNone;
  });
  in.extent = graph_extent(g);
  in.scale = std::max(in.extent.diagonal(), 1e-300);
  in.tol = options.relative_tolerance * in.scale;
  return in;
}

std::optional<Rejection> arc_end_off_curve(const Diagram& g, double tol) {
  const auto off = first_end_off_curve(g, tol);
  if (!off) return std::nullopt;
  RecognitionFailure fail;
  fail.arc = off->arc;
  fail.node = off->node;
  fail.x = g.nodes[off->node].x;
  fail.y = g.nodes[off->node].y;
  fail.amount = off->distance;
  std::ostringstream msg;
  msg << "arc " << off->arc << ": its end node " << off->node << " is " << off->distance
      << " off the arc's curve (tolerance " << tol << ")";
  fail.message = msg.str();
  return Rejection{fail.message, fail};
}

}  // namespace covmap::recognition::stages
