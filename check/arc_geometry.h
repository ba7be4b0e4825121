// Arc geometry for the checker: a parameterised view of an Arc, sampling, boxes, clipping and
// curve intersections. Constructions only (numbers in, numbers out); the decisions with tolerances
// are made by the callers, which pass eps explicitly.
#pragma once

#include <limits>
#include <utility>
#include <vector>

#include "core/arc_sweep.h"
#include "core/box.h"
#include "core/diagram.h"

namespace covmap::check::detail {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
using covmap::kTwoPi;


// An arc as a path p(s), s in [s0, s1]. Circles: s is the angle travelled from the start node (or
// from angle 0 for a full circle), in the arc's sense, so s0 = 0 and s1 = sweep in [0, 2pi] as
// core/arc_sweep.h decides it (a loop from == to is the full circle; two distinct nodes at the
// same angle bound an arc of length zero), the same reading as voronoi/arc_path.h. Lines:
// s is signed length along the unit direction from origin; s0 / s1 are -inf / +inf at kNone ends.
struct ArcPath {
  bool circle = false;
  Point centre;
  double radius = 0.0;
  double start_angle = 0.0;
  double sense = 1.0;  // +1 counter-clockwise, -1 clockwise
  Point origin;
  double ux = 1.0, uy = 0.0;
  double s0 = 0.0, s1 = 0.0;
  bool closed = false;  // a full circle without end nodes
  int from = kNone, to = kNone;
  Point from_point, to_point;  // the end nodes' positions (not projected onto the curve)
  double end_gap = 0.0;        // the larger distance of an end node from the curve

  Point at(double s) const;
  // Unit direction of travel at s.
  Point tangent(double s) const;
  // Length per unit of s.
  double speed() const { return circle ? radius : 1.0; }
  bool bounded() const { return s0 > -kInfinity && s1 < kInfinity; }
};

// Requires valid end indices and a valid curve (the caller checks both first). A Line arc whose
// ends are in the wrong order gets s1 < s0; the caller rejects it.
ArcPath make_arc_path(const Arc& arc, const std::vector<Node>& nodes);

// The parameter of the point of the path's full curve nearest to p (circles: in [0, 2pi)).
double param_of(const ArcPath& path, Point p);
// Distance from p to the arc (its parameter range only).
double distance_to_arc(const ArcPath& path, Point p);
// Distance from p to the arc's full curve.
double distance_to_curve(const ArcPath& path, Point p);
// True when p (assumed on the curve) lies within the parameter range and farther than eps from
// both end nodes.
bool is_interior_point(const ArcPath& path, Point p, double eps);

// count parameters evenly spaced strictly inside the arc. An unbounded line is sampled on its
// stretch inside window; when it misses window, on fallback_length next to its finite end, or
// around the point nearest window's centre for a whole line.
std::vector<double> sample_parameters(const ArcPath& path, int count, const Box& window,
                                      double fallback_length);

// Unit direction of the full curve at p (for a circle, perpendicular to p - centre), either sense.
Point curve_direction_at(const ArcPath& path, Point p);

// Bounding box; unbounded lines are clipped to limit (empty if they miss it). Circle arcs are not
// clipped.
Box bounding_box(const ArcPath& path, const Box& limit);

// The parameter intervals on which the arc is inside box, in increasing order.
std::vector<std::pair<double, double>> clip_to_box(const ArcPath& path, const Box& box);

struct CurveIntersection {
  std::vector<Point> points;
  bool coincident = false;  // the two full curves are the same within eps
};
// Intersection points of the two full curves. Near-tangent pairs within eps count as touching once.
// extent (a length, the diagram's scale) turns eps into the angle under which two lines are
// parallel.
CurveIntersection intersect_curves(const ArcPath& a, const ArcPath& b, double eps, double extent);

bool point_in_polygon(Point p, const std::vector<Point>& polygon);

}  // namespace covmap::check::detail
