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

constexpr double kEps = std::numeric_limits<double>::epsilon();

// How far node v is from arc a's curve, and how far it may be: the tolerance, plus the rounding of
// the numbers that state the curve and the node — `relative` of their size (a file written with d
// digits), and never less than a few ulps (a huge circle of a nearly equal pair of weights carries
// an absolute error ~ε·r that no tolerance relative to the graph's extent absorbs).
struct EndOffCurve {
  int arc = kNone;
  int node = kNone;
  double distance = 0.0;
  double allowed = 0.0;
};
EndOffCurve end_off_curve(const Diagram& g, int a, int v, const InputScale& in) {
  const Arc& arc = g.arcs[a];
  const double x = g.nodes[v].x, y = g.nodes[v].y;
  const Point mid = in.extent.centre();
  const double cx = mid.x, cy = mid.y;
  double off = 0.0, size = 0.0, magnitude = 0.0;
  if (const auto* c = std::get_if<Circle>(&arc.curve)) {
    off = std::abs(std::hypot(x - c->cx, y - c->cy) - c->r);
    size = std::hypot(c->cx - cx, c->cy - cy) + c->r;  // the circle's numbers, in the graph's frame
    magnitude = std::abs(c->cx) + std::abs(c->cy) + c->r;
  } else {
    const auto& l = std::get<Line>(arc.curve);
    off = std::abs((x - l.x) * l.dy - (y - l.y) * l.dx) / std::hypot(l.dx, l.dy);
    size = std::hypot(l.x - cx, l.y - cy) + std::hypot(x - l.x, y - l.y);  // the anchor and the lever
    magnitude = std::abs(l.x) + std::abs(l.y);
  }
  const double rounding = tolerance::kArcEndRoundingUlps * kEps * (magnitude + std::abs(x) + std::abs(y));
  return {a, v, off, in.tol + in.relative * size + rounding};
}

// The box of the middle half of the node coordinates (quartiles in x and in y).
Box middle_half(const Diagram& g) {
  LargeVector<double> xs, ys;
  xs.reserve(g.nodes.size());
  ys.reserve(g.nodes.size());
  for (const Node& n : g.nodes)
    if (std::isfinite(n.x) && std::isfinite(n.y)) xs.push_back(n.x), ys.push_back(n.y);
  if (xs.size() < 8) return Box{};
  auto at = [](LargeVector<double>& v, std::size_t k) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
  };
  const std::size_t lo = xs.size() / 4, hi = xs.size() - 1 - xs.size() / 4;
  Box b;
  b.xmin = at(xs, lo), b.xmax = at(xs, hi), b.ymin = at(ys, lo), b.ymax = at(ys, hi);
  return b;
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
  // Near-degenerate inputs (nearly collinear sites, perturbed grids) put more than 2 % of their
  // nodes 10^7..10^13 extents out, where nearly parallel bisectors meet; the central 98 % box then
  // is that far too, and a tolerance relative to it accepts anything. The middle half of the nodes
  // lies among the sites: the extent is at most kMiddleHalfFactor times its box.
  const Box middle = middle_half(g);
  if (!middle.empty() && middle.diagonal() > 0 && in.extent.diagonal() > tolerance::kMiddleHalfFactor * middle.diagonal()) {
    const double grow = 0.5 * (tolerance::kMiddleHalfFactor - 1.0);
    in.extent = middle.grown(grow * std::max(middle.width(), middle.height()));
  }
  in.scale = in.extent.diagonal();
  // All nodes at one point (the rays of cocircular equal-weight sites) fix no length: the
  // coordinates' own size, or 1, stands in.
  const double magnitude = std::max({std::abs(in.extent.xmin), std::abs(in.extent.xmax), std::abs(in.extent.ymin),
                                     std::abs(in.extent.ymax)});
  if (!(in.scale > tolerance::kCollapsedExtent * magnitude)) in.scale = magnitude > 0 ? magnitude : 1.0;
  in.relative = options.relative_tolerance;
  // The input's coordinates are themselves rounded to ε of their size: far from the origin that is
  // more than a small tolerance relative to the extent.
  in.tol = options.relative_tolerance * in.scale + tolerance::kArcEndRoundingUlps * kEps * magnitude;
  return in;
}

std::optional<Rejection> arc_end_off_curve(const Diagram& g, const InputScale& in, ResidualSummary& residuals) {
  // Per worker: the arc ends off their curves (normally none), in arc order.
  const int workers = worker_count(g.arcs.size());
  std::vector<std::vector<EndOffCurve>> found(workers);
  parallel_chunks(g.arcs.size(), workers, [&](std::size_t b, std::size_t e, int w) {
    for (std::size_t a = b; a < e; ++a)
      for (int v : {g.arcs[a].from, g.arcs[a].to}) {
        if (v == kNone) continue;
        const EndOffCurve off = end_off_curve(g, static_cast<int>(a), v, in);
        if (!(off.distance <= off.allowed)) found[w].push_back(off);
      }
  });
  std::vector<Residual> all;
  std::vector<char> node_seen;
  const EndOffCurve* first = nullptr;
  for (const auto& chunk : found)
    for (const EndOffCurve& off : chunk) {
      if (!first) first = &off;
      if (node_seen.empty()) node_seen.assign(g.nodes.size(), 0);
      if (!node_seen[off.node]) ++residuals.nodes_beyond, node_seen[off.node] = 1;
      all.push_back({ResidualElement::kNode, off.node, g.nodes[off.node].x, g.nodes[off.node].y, off.distance, off.allowed});
    }
  if (!first) return std::nullopt;
  keep_worst(std::move(all), residuals);
  residuals.tolerance = in.tol;
  RecognitionFailure fail;
  fail.arc = first->arc;
  fail.node = first->node;
  fail.x = g.nodes[first->node].x;
  fail.y = g.nodes[first->node].y;
  fail.amount = first->distance;
  fail.nodes_beyond = residuals.nodes_beyond;
  std::ostringstream msg;
  msg << residuals.nodes_beyond << " node(s) lie off their arcs' curves beyond the tolerance; the first: arc "
      << first->arc << ": its end node " << first->node << " is " << first->distance
      << " off the arc's curve (allowed " << first->allowed << ")";
  fail.message = msg.str();
  return Rejection{fail.message, fail};
}

}  // namespace covmap::recognition::stages
