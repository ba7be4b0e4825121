// Arcs seen from one of their nodes. Going around a node composes inversions in the arcs there;
// in plane coordinates the inversion in an arc of a huge circle (nearly equal weights) has matrix
// entries ~R² that cancel in the composition. In the node's own frame z' = (z - v) / L, with the
// arc forced through the origin and its form scaled to a largest coefficient of 1, the same
// inversion is a near-reflection with O(1) entries.
#pragma once

#include <algorithm>
#include <cmath>
#include <variant>

#include "mobius/generalized_circle.h"
#include "core/diagram.h"

namespace covmap::mobius {

// The arc's curve in the frame z' = (z - v) / L of one of its nodes v: forced through the origin
// (the node is on the arc up to rounding or, for cleaned maps, up to the fit) and normalised.
inline GeneralizedCircle curve_through_origin(const Arc& a, Complex v, double L) {
  if (const auto* c = std::get_if<Circle>(&a.curve)) {
    const Complex centre = (Complex(c->cx, c->cy) - v) / L;
    const double s = std::max(1.0, std::abs(centre));
    return {1.0 / s, -centre / s, 0.0};
  }
  const auto& l = std::get<Line>(a.curve);
  GeneralizedCircle g = GeneralizedCircle::line({0.0, 0.0}, {l.dx, l.dy});
  g.B /= std::abs(g.B);
  return g;
}

}  // namespace covmap::mobius
