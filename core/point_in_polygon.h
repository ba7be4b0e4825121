// Point in polygon by the even–odd rule: the one reading of "is this point inside these rings" for
// every library and test but the independent checker (check/ keeps its own, so that it shares no
// code with what it checks).
//
// Rings: a ring is its vertices in order with the closing edge implied; a repeated closing vertex
// (front == back) is allowed, its zero-length edge crosses nothing. Any orientation: the answer
// does not depend on it.
// Several rings (holes): a point is inside when it lies inside an odd number of them. For an outer
// ring with holes inside it that do not overlap, that is "inside the outer ring and outside every
// hole"; for overlapping rings it is the even–odd fill of SVG.
// Boundary: the answer is that of a point just above and just right of p. On axis-parallel edges
// this is exact: a point on a left or bottom edge is inside, on a right or top edge outside, as for
// the half-open box [x0, x1) × [y0, y1), so cells sharing such edges claim each point once. On any
// other edge the crossing's x is rounded, so a point within rounding of it may fall either side:
// callers ask about points off the boundary, or accept either answer there.
// Coordinates must be finite. Cost O(vertices) per point; nothing is allocated.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/coverage_cells.h"
#include "core/diagram.h"

namespace covmap {

// Whether p is inside `ring`: a ray from p towards +x crosses its edges an odd number of times.
// Each edge counts when it spans p's height half-open (one end above p, the other not) and
// crosses the ray strictly right of p.
inline bool inside_ring(std::span<const Point> ring, Point p) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
        p.x < (ring[j].x - ring[i].x) * (p.y - ring[i].y) / (ring[j].y - ring[i].y) + ring[i].x)
      inside = !inside;
  }
  return inside;
}

// Even–odd over all `rings`: inside an odd number of them.
inline bool inside_rings(std::span<const std::vector<Point>> rings, Point p) {
  bool inside = false;
  for (const auto& ring : rings) inside = inside != inside_ring(ring, p);
  return inside;
}

// A cell polygon's outer ring and holes, even–odd.
inline bool inside_polygon(const CellPolygon& polygon, Point p) {
  return inside_ring(polygon.outer, p) != inside_rings(polygon.holes, p);
}

}  // namespace covmap
