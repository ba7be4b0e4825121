// Geometry of one diagram arc as a parametrised path, for the algorithms that read diagrams (face
// tracing, clipping). Constructions only: numbers in, numbers out.
//
// Circles: parameter s is the angle travelled from the start (the `from` node, or angle 0 for a
// full circle) in the arc's sense, s ∈ [0, sweep], sweep ∈ (0, 2π]. Lines: s is the signed length
// along the unit direction from the line's anchor point; ±∞ at kNone ends.
#pragma once

#include <limits>
#include <vector>

#include "voronoi/diagram.h"

namespace covmap::voronoi {

inline constexpr double kPathInfinity = std::numeric_limits<double>::infinity();

struct ArcPathView {
  bool circle = false;
  double cx = 0.0, cy = 0.0, r = 0.0;
  double start_angle = 0.0;
  double sense = 1.0;  // +1 counter-clockwise, -1 clockwise (circles)
  double ox = 0.0, oy = 0.0, ux = 1.0, uy = 0.0;  // lines: anchor and unit direction
  double s0 = 0.0, s1 = 0.0;

  Point at(double s) const;
  // Unit direction of travel at s.
  Point tangent(double s) const;
  // Signed curvature of the path (positive when it turns left), 0 for lines.
  double curvature() const { return circle ? sense / r : 0.0; }
};

ArcPathView arc_path(const Arc& arc, const std::vector<Node>& nodes);

// Parameters (within [s0, s1]) where the path crosses the segment a–b, in increasing order.
std::vector<double> path_segment_crossings(const ArcPathView& path, Point a, Point b);

}  // namespace covmap::voronoi
