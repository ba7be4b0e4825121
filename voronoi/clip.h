// covmap::voronoi::clip_diagram — a diagram restricted to a simple polygon (coverage maps cover a
// bounded area).
//
// Contract: `polygon` is simple and counter-clockwise (io::parse_clip guarantees both). Returns the
// part of `d` inside it: arcs cut where they cross the boundary (new nodes there), the boundary
// itself as frame arcs (Arc::frame, the inside site on the left, kNone outside), faces re-traced,
// and Diagram::clip set. Sites are kept (indices stay valid); a site whose region misses the
// polygon simply has no face. Crossings are computed in floating point: clipping is a
// construction, not a combinatorial decision of the diagram; crossings within
// tolerance::kClipSnap of a polygon vertex are snapped onto it.
//
// Cost: O((arcs + nodes) × polygon vertices) plus face tracing. Throws ClipTooLarge, before any
// work, when that product exceeds tolerance::kMaxClipWork.
#pragma once

#include <stdexcept>
#include <vector>

#include "core/diagram.h"

namespace covmap::voronoi {

class ClipTooLarge : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

Diagram clip_diagram(const Diagram& d, const std::vector<Point>& polygon);

}  // namespace covmap::voronoi
