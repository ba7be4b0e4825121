// Path geometry for the SVG writer (internal to io/, declared here so tests can check it).
//
// Everything is in world coordinates (y up); the writer flips y with a transform, so an arc's
// sweep flag is simply its orientation: 1 for counter-clockwise travel.
//
// Unbounded faces are closed with a "far box": a rectangle strictly containing the view box, every
// node, every circle and a point of every full line. Each ray to infinity is cut where it leaves the
// far box, and the pieces of a face's boundary between infinity and infinity ("chains") are joined
// by walking counter-clockwise along the far box from one chain's exit to the next chain's entry.
// That is the face's side because every boundary keeps its face on the left. Since the far box
// lies outside the view box, the walk is never visible.
#pragma once

#include <string>

#include "core/box.h"
#include "core/diagram.h"

namespace covmap::report::detail {


// The far box for `diagram` drawn in `view` (see above).
Box far_box(const Diagram& diagram, const Box& view);

// SVG path data ("M ... A ... L ...") for one arc, rays cut at `far`.
std::string arc_path(const Diagram& diagram, int arc, const Box& far);

// SVG path data for one face: one closed subpath per boundary cycle, chains through infinity joined
// along `far`; an unbounded face without such chains gets `far` itself as its outer subpath. Meant
// for fill-rule evenodd.
std::string face_path(const Diagram& diagram, const Face& face, const Box& far);

// A number for SVG: ten significant digits, far below a pixel at any sensible zoom.
std::string svg_number(double v);

}  // namespace covmap::report::detail
