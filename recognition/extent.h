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

}  // namespace covmap::recognition
