// Lemma 5 (seed paper 5, §4.4), one home for exact and for least-squares recognition: going once
// around a node, inverting in each arc there in turn, maps the site of the face one starts in to
// itself. The fixed set of the composed map is where that site may lie: for an odd number of arcs
// (an anti-Möbius map) a circle, or two points, or nothing; for an even number (a Möbius map) at
// most two points, or everything (the identity: no constraint).
//
// The composition runs in the node's own frame z' = (z - origin) / unit (node_frame.h): there
// every arc passes through the origin and is a near-reflection with O(1) matrix entries, where in
// plane coordinates an arc of a huge circle (nearly equal weights) has entries ~R² that cancel.
// Any unit of the node's neighbourhood's size serves; callers pick one they have at hand.
//
// Two readings of the fixed set, by the same composed map:
// - exact_fixed_set (recognize(): exact graphs, up to rounding): the two real forms of an
//   anti-Möbius map's fixed-point equation are proportional for a circle and meet in the fixed
//   points otherwise; matrix_tolerance (relative to the largest entry) decides "proportional" and
//   "zero".
// - least_squares_fixed_circle / other_fixed_point (the audit's start values: arcs fitted to
//   staircases, no exact solution): the principal direction of the two forms is the circle; an
//   even-degree node gives its second fixed point when the map is not the identity.
#pragma once

#include <optional>
#include <vector>

#include "core/diagram.h"
#include "mobius/generalized_circle.h"
#include "mobius/mobius.h"
#include "mobius/node_frame.h"

namespace covmap::mobius {

// The frame of a node: z' = (z - origin) / unit.
struct NodeFrame {
  Complex origin;
  double unit = 1.0;
  Complex to_plane(Complex z) const { return origin + unit * z; }
  GeneralizedCircle to_plane(const GeneralizedCircle& g) const;
};

// One step around a node: `composed` followed by the inversion in `arc`, seen from `frame`.
inline Mobius then_invert_in(const Mobius& composed, const Arc& arc, const NodeFrame& frame) {
  return Mobius::inversion(curve_through_origin(arc, frame.origin, frame.unit)).after(composed);
}

// Where the site of the start face may lie, in frame coordinates.
struct NodeConstraint {
  bool any = false;        // the identity: no constraint
  bool is_circle = false;  // a whole circle (or line) of fixed points
  GeneralizedCircle circle;
  std::vector<Complex> points;  // otherwise: the fixed points (none, one or two)
  // Odd degree, no fixed point: the two circles whose intersection the fixed set is miss each
  // other by this much (in frame units; infinite when a form is imaginary or both are lines).
  double gap = 0.0;
};

NodeConstraint exact_fixed_set(const Mobius& composed, double matrix_tolerance);

// Odd degree (composed.conjugated()): the least-squares solution circle in frame coordinates (the
// dominant right singular vector of the two forms' coefficients).
GeneralizedCircle least_squares_fixed_circle(const Mobius& composed);
// Even degree: the fixed point other than the node itself (the origin), unless the map is the
// identity to within `identity_tolerance` (its c entry relative to the largest entry) or that
// point is the origin too (|point| below identity_tolerance).
std::optional<Complex> other_fixed_point(const Mobius& composed, double identity_tolerance);

}  // namespace covmap::mobius
