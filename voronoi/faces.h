// covmap::voronoi::trace_faces — the faces of a diagram whose arcs name their sites.
//
// Contract: `d.arcs` must form a planar arc graph in which every arc names the sites on its left
// and right (kNone outside a frame). trace_faces replaces `d.faces` by the connected components of
// every site's region: boundary cycles of half-arcs with the face on their left, the outer cycle
// first (bounded faces; a cycle through infinity for unbounded faces bounded by lines), then holes.
// Each face is marked orphan unless it contains its own site. Works on the engine's output and on
// any other site-labelled arc graph. At a node where one site's region touches itself the next
// half-arc is chosen by angle; elsewhere the labels alone decide. With FaceLabels::kGeometry every
// continuation is chosen by angle (tangent, then curvature), for graphs without site labels.
#pragma once

#include <span>

#include "core/diagram.h"
#include "core/large_buffer.h"

namespace covmap::voronoi {

enum class FaceLabels {
  kSites,     // arcs name their sites; faces are the components of each site's region
  kGeometry,  // arcs need not name sites (an input graph): continuations are chosen by angle and
              // faces get site kNone; nesting is decided by containment
};

// Per half-arc (2·arc for the arc's direction, 2·arc + 1 against it): the face it bounds and the
// half-arc following it in that face's boundary cycle; kNone for half-arcs on no closed cycle.
struct FaceIndex {
  LargeVector<int> face_of_half;
  LargeVector<int> next_half;
};

// When `index` is given it is filled too (what the tracing knows anyway; rebuilding it from the
// faces costs a pass of random writes over every half-arc).
void trace_faces(Diagram& d, FaceLabels labels = FaceLabels::kSites, FaceIndex* index = nullptr);

// True when p lies inside the region enclosed by `cycle` (half-arcs with the region on their left;
// a cycle may pass through infinity). Used for containment of holes and sites.
bool cycle_contains(const Diagram& d, std::span<const HalfArc> cycle, Point p);

}  // namespace covmap::voronoi
