// How well an arc of the input states the sites on its two sides (internal to the recognition
// library; the site collection and the MWVD check read it the same way).
//
// A site is the mirror of its neighbours in its arcs; an arc whose numbers have size S (in the
// input's frame: a circle's centre and radius, a line's anchor) states it only to about τ·S
// (τ = RecognitionOptions::relative_tolerance). A site's spread is the size of the numbers of its
// best-stated arc, in extents and at least 1: an orphan face far out (nearly equal weights put
// one 10¹⁰ extents away) is stated only by its huge circles and fixes its site to τ times their
// size, not τ times the extent.
#pragma once

#include "core/diagram.h"
#include "core/large_buffer.h"

namespace covmap::recognition {

// The spread one arc gives the sites on its sides (centre, scale: the input's extent's centre and
// diagonal, in the arc's coordinates): a circle by its centre and radius, a line by its anchor and
// its direction's lever to line_read_at, the point the line is read at (its anchor: no lever);
// 1 for frame arcs and when scale is 0.
double arc_site_spread(const Arc& arc, Point centre, double scale, Point line_read_at);

// Per face of g (face_of_half: per half-arc 2a / 2a + 1 of arc a, its face or kNone), the
// smallest spread over its arcs as the reconstruction reads them: a line at the node it mirrors
// sites about (mobius::arc_bisector), which for an orphan far out lies as far out as its circles;
// 1 for a face with no arc that states it.
LargeVector<double> face_spreads(const Diagram& g, const LargeVector<int>& face_of_half, Point centre, double scale);

}  // namespace covmap::recognition
