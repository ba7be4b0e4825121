// Crossing edges among the rings of one polygon (internal to io/, used by the coverage-map reader).
//
// A proper crossing is two edges whose relative interiors meet in a single point at which they
// pass through each other: each edge has the endpoints of the other strictly on opposite sides.
// Edges that only touch (an endpoint on the other edge, a shared vertex) or overlap along a line
// are not proper crossings; neither are consecutive edges, which share a vertex. The decision is
// exact (io/polygon_check.h orientation(): filtered, exact fallback), so no tolerance is involved.
//
// Cost: edges are bucketed in a sparse grid whose cell size is the median edge length (enlarged so
// that long edges occupy at most about kCellsPerEdge cells each on average), and only edges sharing
// a cell are compared: O(E log E) for E edges of evenly sized rings such as exported maps. Many
// short edges packed into one cell next to a few long edges make it quadratic in the worst case.
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

// The crossing with the smallest (first, second) among all proper crossings between edges of the
// rings (within one ring or between two), or nullopt if there is none. Rings are implicitly closed,
// have at least 3 vertices and finite coordinates. The answer does not depend on the grid.
std::optional<Crossing> first_crossing(std::span<const std::vector<Point>> rings);

}  // namespace covmap::io::detail
