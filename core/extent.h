// The size of a graph for relative tolerances. Nodes of nearly tangent bisectors can lie 10⁴ times
// farther out than the sites; a plain bounding box would then make every tolerance 10⁴ times too
// loose. The extent is the diagonal of the box of the central 98% of node coordinates (all of them
// for graphs of fewer than 100 nodes).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/box.h"
#include "core/diagram.h"
#include "core/large_buffer.h"

namespace covmap {

// The central 98 % of a set of coordinates (all of them below 100): order statistics by selection,
// linear in the number of points. No points: the zero box at the origin (a diagonal of 0).
inline Box central_extent(LargeVector<double> xs, LargeVector<double> ys) {
  Box e{0, 0, 0, 0};
  if (xs.empty()) return e;
  const std::size_t cut = xs.size() < 100 ? 0 : xs.size() / 100;
  auto at = [](LargeVector<double>& v, std::size_t k) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
  };
  e.xmin = at(xs, cut), e.xmax = at(xs, xs.size() - 1 - cut);
  e.ymin = at(ys, cut), e.ymax = at(ys, ys.size() - 1 - cut);
  return e;
}

inline Box robust_extent(const std::vector<Node>& nodes) {
  LargeVector<double> xs, ys;
  xs.reserve(nodes.size());
  ys.reserve(nodes.size());
  for (const auto& n : nodes) {
    if (!std::isfinite(n.x) || !std::isfinite(n.y)) continue;
    xs.push_back(n.x);
    ys.push_back(n.y);
  }
  return central_extent(std::move(xs), std::move(ys));
}

// The extent of a whole graph: its nodes, and for graphs with few or no nodes (disjoint circles and
// lines, paper 5 §3) also the boxes of its full circles and the anchor points of its whole lines.
inline Box graph_extent(const Diagram& g) {
  LargeVector<double> xs, ys;
  xs.reserve(g.nodes.size());
  ys.reserve(g.nodes.size());
  auto add = [&](double x, double y) {
    if (std::isfinite(x) && std::isfinite(y)) xs.push_back(x), ys.push_back(y);
  };
  for (const auto& n : g.nodes) add(n.x, n.y);
  for (const auto& a : g.arcs) {
    if (a.from != kNone || a.to != kNone) continue;
    if (const auto* c = std::get_if<Circle>(&a.curve)) {
      add(c->cx - c->r, c->cy - c->r);
      add(c->cx + c->r, c->cy + c->r);
    } else {
      const auto& l = std::get<Line>(a.curve);
      add(l.x, l.y);
    }
  }
  return central_extent(std::move(xs), std::move(ys));
}

}  // namespace covmap
