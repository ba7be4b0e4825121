// Crossing edges among the rings of one polygon (internal to io/, used by the coverage-map reader).
//
// A proper crossing is two edges whose relative interiors meet in a single point at which they
// pass through each other: each edge has the endpoints of the other strictly on opposite sides.
// Edges that only touch (an endpoint on the other edge, a shared vertex) or overlap along a line
// are not proper crossings; neither are consecutive edges, which share a vertex. The decision is
// exact (core/orientation.h: filtered, exact fallback), so no tolerance is involved.
//
// Cost: O(E log E) time and O(E) memory for E edges, whatever their shape: the sweep of
// io/segment_sweep.h, which tests only edges that are neighbours on the sweep line and is proved
// there to find a proper crossing whenever one exists, however many edges touch or overlap.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "core/diagram.h"

namespace covmap::io::detail {

// Edge `edge` of ring `ring` runs from vertex edge to vertex (edge + 1) % size.
struct EdgeRef {
  std::size_t ring = 0;
  std::size_t edge = 0;
  friend auto operator<=>(const EdgeRef&, const EdgeRef&) = default;
};

struct Crossing {
  EdgeRef first;   // first < second
  EdgeRef second;
};

// Whether the segments p1-p2 and q1-q2 cross properly (see above). Exact.
bool properly_cross(Point p1, Point p2, Point q1, Point q2);

// One proper crossing between edges of the rings (within one ring or between two), or nullopt if
// there is none: exact in both directions. Which crossing, when there are several: the first that
// the sweep meets, not the one of smallest (first, second) (that one is not known to be findable in
// O(E log E)); the answer depends only on the rings, so the same input always names the same pair.
// Rings are implicitly closed and have finite coordinates; edges of zero length (repeated
// consecutive vertices) are ignored, as they cannot cross anything properly.
std::optional<Crossing> find_crossing(std::span<const std::vector<Point>> rings);

}  // namespace covmap::io::detail
