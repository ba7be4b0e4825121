// The one axis-parallel box type of covmap: bounds of points, arcs, views and grids.
//
// Contract: a default Box is empty (+inf minima, -inf maxima), so adding points grows it from
// nothing. add() takes every point as given; add_finite() skips points with a non-finite
// coordinate (rays to infinity, NaN from a failed construction). A box is finite() only when all
// four bounds are. No tolerances: grown() widens by an explicit margin.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/diagram.h"

namespace covmap {

struct Box {
  double xmin = std::numeric_limits<double>::infinity();
  double ymin = std::numeric_limits<double>::infinity();
  double xmax = -std::numeric_limits<double>::infinity();
  double ymax = -std::numeric_limits<double>::infinity();

  bool empty() const { return xmin > xmax || ymin > ymax; }
  bool finite() const {
    return std::isfinite(xmin) && std::isfinite(ymin) && std::isfinite(xmax) && std::isfinite(ymax);
  }
  double width() const { return xmax - xmin; }
  double height() const { return ymax - ymin; }
  // The diagonal's length; 0 for an empty box.
  double diagonal() const { return empty() ? 0.0 : std::hypot(width(), height()); }
  Point centre() const { return {(xmin + xmax) / 2, (ymin + ymax) / 2}; }

  void add(double x, double y) {
    xmin = std::min(xmin, x), ymin = std::min(ymin, y);
    xmax = std::max(xmax, x), ymax = std::max(ymax, y);
  }
  void add(Point p) { add(p.x, p.y); }
  void add_finite(double x, double y) {
    if (std::isfinite(x) && std::isfinite(y)) add(x, y);
  }
  void add_box(const Box& b) {
    xmin = std::min(xmin, b.xmin), ymin = std::min(ymin, b.ymin);
    xmax = std::max(xmax, b.xmax), ymax = std::max(ymax, b.ymax);
  }

  Box grown(double margin) const { return Box{xmin - margin, ymin - margin, xmax + margin, ymax + margin}; }
  bool contains(Point p) const { return p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax; }
  // Euclidean distance from p to the box (0 inside or on it). Precondition: not empty().
  double distance_to(Point p) const {
    return std::hypot(std::max({xmin - p.x, 0.0, p.x - xmax}), std::max({ymin - p.y, 0.0, p.y - ymax}));
  }
  bool overlaps(const Box& o) const {
    return !empty() && !o.empty() && xmin <= o.xmax && o.xmin <= xmax && ymin <= o.ymax && o.ymin <= ymax;
  }
};

}  // namespace covmap
