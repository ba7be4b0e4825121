// Validity of a clip polygon: simple, non-degenerate, and its orientation.
//
// Decisions here are exact: they are built on core/orientation.h, so "do these edges touch?" never
// depends on a tolerance.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "core/diagram.h"
#include "core/orientation.h"

namespace covmap::io {

// Why `ring` (vertices in order, the closing edge implied, no repeated closing vertex) is not a
// usable clip polygon, or nullopt if it is one. Checked: at least 3 vertices, finite coordinates,
// no two consecutive vertices equal, not all collinear (non-zero area), and no two edges meeting
// other than consecutive edges at their shared vertex (this includes touching and overlapping).
// The first failed check is reported; for a polygon that is not simple, one meeting is named: a
// vertex visited twice, or a pair of edges (the first pair the sweep of io/segment_sweep.h finds,
// which depends only on the ring, not necessarily the pair of smallest indices). Cost
// O(n log n) time and O(n) memory in the number of vertices.
std::optional<std::string> polygon_defect(std::span<const Point> ring);

// +1 if the ring runs counter-clockwise, -1 if clockwise. Precondition: polygon_defect(ring) is
// nullopt.
int ring_orientation(std::span<const Point> ring);

}  // namespace covmap::io
