// Circles and lines fitted to boundary chains. Internal to map_cleaning.
//
// fit_curve: the circle or line minimizing the (Huber-robust) sum of squared geometric distances
// to the points. The circle is parametrized in the curvature form of Pratt / Chernov–Lesort,
//     A (x² + y²) + B x + C y + D = 0,  B² + C² − 4AD = 1,
// with (B, C) = √(1 + 4AD) (cos θ, sin θ), in coordinates centred on a middle chain point and
// scaled to the chain's extent: A = 0 is exactly a line, and radii of 10^9 extents are as well
// conditioned as small ones (the distance 2P / (1 + √(1 + 4AP)) has no cancellation). It starts
// from the orthogonal line fit and from Kåsa's algebraic circle and refines both by
// Levenberg–Marquardt on the geometric distance; the line is returned when its rms per degree of
// freedom is within `line_preference` of the circle's; a line runs the way the points do.
// force_circle: never a line (closed loops). Fewer than 3 points: the line through the first and
// last.
//
// fit_through: the same with the curve forced through two points p ≠ q (the arc's end nodes): the
// line pq, or the best circle of the one-parameter family through p and q.
//
// distance_to: signed geometric distance of a point to a circle (positive outside) or line
// (positive on the left of its direction), and its gradient (a unit vector).
#pragma once

#include <span>

#include "cleaning/map_cleaning.h"
#include "core/diagram.h"

namespace covmap::cleaning {

// huber: the robust loss's threshold, map units.
FittedCurve fit_curve(std::span<const Point> points, double huber, double line_preference,
                      bool force_circle);

Curve fit_through(std::span<const Point> points, Point p, Point q,
                           const Curve& guess, double huber);

// rms and largest absolute geometric distance of the points to the curve.
void deviation(std::span<const Point> points, const Curve& curve, double& rms, double& max);

double distance_to(const Curve& curve, Point p, Point* gradient = nullptr);

}  // namespace covmap::cleaning
