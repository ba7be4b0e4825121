// The size of a graph for relative tolerances. Nodes of nearly tangent bisectors can lie 10⁴ times
// farther out than the sites; a plain bounding box would then make every tolerance 10⁴ times too
// loose. The extent is the diagonal of the box of the central 98% of node coordinates (all of them
// for graphs of fewer than 100 nodes).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "voronoi/diagram.h"

namespace covmap::recognition {

struct Extent {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  double diagonal() const { return std::hypot(xmax - xmin, ymax - ymin); }
};

inline Extent robust_extent(const std::vector<voronoi::Node>& nodes) {
  Extent e;
  if (nodes.empty()) return e;
  std::vector<double> xs, ys;
  xs.reserve(nodes.size());
  ys.reserve(nodes.size());
  for (const auto& n : nodes) {
    if (!std::isfinite(n.x) || !std::isfinite(n.y)) continue;
    xs.push_back(n.x);
    ys.push_back(n.y);
  }
  if (xs.empty()) return e;
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  const std::size_t cut = xs.size() < 100 ? 0 : xs.size() / 100;
  e.xmin = xs[cut], e.xmax = xs[xs.size() - 1 - cut];
  e.ymin = ys[cut], e.ymax = ys[ys.size() - 1 - cut];
  return e;
}

// The extent of a whole graph: its nodes, and for graphs with few or no nodes (disjoint circles and
// lines, paper 5 §3) also the boxes of its full circles and the anchor points of its whole lines.
inline Extent graph_extent(const voronoi::Diagram& g) {
  std::vector<voronoi::Node> points = g.nodes;
  for (const auto& a : g.arcs) {
    if (a.from != voronoi::kNone || a.to != voronoi::kNone) continue;
    if (const auto* c = std::get_if<voronoi::Circle>(&a.curve)) {
      points.push_back({c->cx - c->r, c->cy - c->r});
      points.push_back({c->cx + c->r, c->cy + c->r});
    } else {
      const auto& l = std::get<voronoi::Line>(a.curve);
      points.push_back({l.x, l.y});
    }
  }
  return robust_extent(points);
}

}  // namespace covmap::recognition
