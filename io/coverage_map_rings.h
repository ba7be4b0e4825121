// Ring validation for the coverage-map reader (internal to io/): from the positions of one polygon
// as read (and projected), to a MapPolygon or the reasons it is not one.
//
// The steps, in order, each only on what passed the one before:
//   1. drop consecutive repeated vertices and the closing vertex (silently: they change nothing);
//   2. per ring: at least 3 vertices left; not all on one line; not doubling back at its lowest
//      vertex (that vertex decides the orientation, so it must turn one way or the other);
//   3. no proper crossing among the edges of all rings of the polygon (coverage_map_crossings.h);
//   4. orientation: outer ring counter-clockwise, holes clockwise.
// Decisions are exact (io/polygon_check.h orientation()); nothing here has a tolerance.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/coverage_map.h"

namespace covmap::io::detail {

// One ring of a polygon as it will be checked.
struct RingInput {
  std::vector<Point> read;       // positions as in the file (lon/lat or x/y), closing one included
  std::vector<Point> projected;  // the same positions in the plane, index for index
};

// Where a polygon sits in its feature, for messages: "outer ring", "hole 2 of polygon 1".
struct PolygonPlace {
  std::size_t polygon = 0;
  bool multi = false;  // a member of a MultiPolygon (then messages name the polygon)
};

std::string ring_name(const PolygonPlace& place, std::size_t ring);

// Validates and normalizes one polygon (rings[0] outer, the rest holes). On success returns the
// polygon; otherwise appends one message per defect found to `problems` and returns nullopt.
std::optional<MapPolygon> make_map_polygon(const std::vector<RingInput>& rings, const PolygonPlace& place,
                                           std::vector<std::string>& problems);

}  // namespace covmap::io::detail
