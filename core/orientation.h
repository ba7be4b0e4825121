// The one exact 2D orientation predicate of covmap.
//
// Contract: orientation(a, b, c) is the exact sign of the turn a -> b -> c for any finite doubles,
// provided no non-zero coordinate is smaller than 2^-480 (about 1e-144) times the largest of the
// six: the exact stage scales all six by one power of two so the largest is below 1, and then only
// a product of two coordinates both that much smaller than the largest can underflow. Coordinates
// of any one magnitude, from 1e-300 to 1e308, are exact. A floating-point filter (Shewchuk's
// orient2d stage A) decides almost every call; when it cannot (or when its products overflow or
// underflow), the determinant is expanded into exact products of the scaled coordinates and their
// sum's sign computed exactly (expansion arithmetic), so no decision built on it depends on a
// tolerance.
#pragma once

namespace covmap {

struct Point;

// +1 counter-clockwise (c left of a -> b), -1 clockwise, 0 collinear.
int orientation(Point a, Point b, Point c);

}  // namespace covmap
