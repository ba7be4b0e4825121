// covmap::circle_arc_sweep — how much of its circle a circle arc covers: the one reading of an arc's
// extent shared by the algorithms that read diagrams (voronoi/arc_path.h) and the independent
// checker (check/arc_geometry.h), so that both see the same arcs.
//
// Contract (also stated in core/diagram.h and docs/FORMATS.md): the extent of a circle arc is
// decided by its end node indices first, by angles only where the indices cannot decide:
//   from == to == kNone   the full circle, from angle 0;
//   from == to            a loop: the full circle, from the node's angle round to it again;
//   from != to            the angle swept from `from` to `to` in the arc's sense, in [0, 2π)
//                         (swept_angle). Two distinct nodes at the same angle (the swept angle is 0,
//                         or rounds to 2π) bound an arc of length zero: a full circle always has one
//                         node or none.
// Constructions only: numbers in, numbers out.
#pragma once

#include <cmath>
#include <vector>

#include "core/diagram.h"

namespace covmap {

inline constexpr double kTwoPi = 6.283185307179586476925286766559;

// An angle reduced to [0, 2π). A tiny negative angle, which rounds to 2π when 2π is added, is 0.
inline double wrap_angle(double a) {
  a = std::fmod(a, kTwoPi);
  if (a < 0.0) a += kTwoPi;
  if (a >= kTwoPi) a -= kTwoPi;
  return a;
}

// The angle swept around a centre from direction (ax, ay) to direction (ex, ey) (each a node minus
// the centre), counter-clockwise when ccw, in [0, 2π): one atan2 of the two directions' cross and
// dot products (no cancellation of two large angles when the sweep is small). Exactly 0 when the
// directions are parallel and alike.
inline double swept_angle(double ax, double ay, double ex, double ey, bool ccw) {
  const double turn = std::atan2(ax * ey - ay * ex, ax * ex + ay * ey);  // in [-π, π]
  return wrap_angle(ccw ? turn : -turn);
}

// Where a circle arc starts (the angle of its `from` node around the centre, 0 without nodes) and
// how far it turns in its own sense (sweep ∈ [0, 2π], 2π exactly for full circles and loops).
struct CircleSweep {
  double start_angle = 0.0;
  double sweep = kTwoPi;
  bool full = true;  // a full circle or a loop (from == to)
};

// `arc` must be a circle arc with valid end indices into `nodes` (both kNone, or both set).
inline CircleSweep circle_arc_sweep(const Arc& arc, const Circle& c, const std::vector<Node>& nodes) {
  CircleSweep out;
  if (arc.from == kNone) return out;
  const Node& a = nodes[arc.from];
  out.start_angle = std::atan2(a.y - c.cy, a.x - c.cx);
  if (arc.from == arc.to) return out;
  const Node& b = nodes[arc.to];
  out.sweep = swept_angle(a.x - c.cx, a.y - c.cy, b.x - c.cx, b.y - c.cy, arc.ccw);
  out.full = false;
  return out;
}

}  // namespace covmap
