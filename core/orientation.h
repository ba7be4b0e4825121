// The one exact 2D orientation predicate of covmap.
//
// Contract: orientation(a, b, c) is the exact sign of the turn a -> b -> c for any finite doubles
// whose pairwise products neither overflow nor underflow (coordinates well within 1e-150 .. 1e150
// in magnitude; any real map coordinate is). A floating-point filter (Shewchuk's orient2d stage A)
// decides almost every call; when it cannot, the determinant is expanded into exact products of
// the input coordinates and their sum's sign computed exactly (expansion arithmetic), so no
// decision built on it depends on a tolerance.
#pragma once

namespace covmap {

struct Point;

// +1 counter-clockwise (c left of a -> b), -1 clockwise, 0 collinear.
int orientation(Point a, Point b, Point c);

}  // namespace covmap
