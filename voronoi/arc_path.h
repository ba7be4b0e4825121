// Geometry of one diagram arc as a parametrised path, for the algorithms that read diagrams (face
// tracing, clipping). Constructions only: numbers in, numbers out.
//
// Circles: parameter s is the angle travelled from the start (the `from` node, or angle 0 for a
// full circle) in the arc's sense, s ∈ [0, sweep], sweep ∈ [0, 2π] as core/arc_sweep.h decides it
// (the checker reads arcs the same way: check/arc_geometry.h). Lines: s is the signed length
// along the unit direction from the line's anchor point; ±∞ at kNone ends.
#pragma once

#include <array>
#include <limits>
#include <vector>

#include "core/box.h"
#include "core/diagram.h"

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
  // The parameter of the point of the full curve nearest to q (circles: in [0, 2π), whatever the
  // arc's extent).
  double param_of(Point q) const;
  // Unit direction of travel at s.
  Point tangent(double s) const;
  // Signed curvature of the path (positive when it turns left), 0 for lines.
  double curvature() const { return circle ? sense / r : 0.0; }
};

ArcPathView arc_path(const Arc& arc, const std::vector<Node>& nodes);

// A monotone stand-in for atan2 (the "diamond angle"), in [0, kPseudoTurn): a full turn is 4 and
// the slope per radian lies between 1/2 and 1. Orders directions without trigonometry.
inline constexpr double kPseudoTurn = 4.0;
double pseudo_angle(double x, double y);

// Axis-aligned bounds of an arc {xmin, ymin, xmax, ymax}: its ends and the circle's axis-extreme
// points within its sweep, widened by a few units in the last place so that rounding cannot make
// them miss the arc; ±infinity for a line arc with an end at infinity. `from` and `to` are the
// arc's end nodes (ignored where the arc has none).
Box arc_bounds(const Arc& arc, const Node& from, const Node& to);
Box arc_bounds(const Arc& arc, const std::vector<Node>& nodes);

// Parameters (within [s0, s1]) where the path crosses the segment a–b, in increasing order.
std::vector<double> path_segment_crossings(const ArcPathView& path, Point a, Point b);

}  // namespace covmap::voronoi
