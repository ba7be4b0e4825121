// The engine's own structural check of what it is about to return, cheap enough to run always.
//
// Contract: self_check(d) returns normally when every site bounds some arc (with two or more
// sites: each owns a neighbourhood of itself), every node is finite, every arc end lies on its
// arc's curve (tolerance::kSelfCheckOnCurve of the sites' extent, plus kSelfCheckUlps of the
// magnitudes involved: the checker in check/ allows more), every bounded line arc runs along its
// direction (to within that allowance: split nodes may round an ulp out of order), and the arcs
// of each circle (huge ones excepted, tolerance::kHugeCircleRatio), in the order the facet walk
// found them, turn around it exactly once as their rounded nodes say. The last is what readers rely on when they take an
// arc's sweep from its end nodes: a tiny arc whose ends rounded out of order, or a near-full arc
// whose ends rounded to one point, would be read as the complementary arc. Otherwise it throws
// EngineFailure naming the arc's sites (the engine must never return a diagram it knows to be
// wrong; the caller reports an internal error, not bad input).
//
// It expects the arcs of one site pair contiguous and in walk order, as the extractors emit them
// (before flat arcs are straightened).
#pragma once

#include "core/diagram.h"

namespace covmap::voronoi::engine {

void self_check(const Diagram& d);

// Pieces shared with the extractors (engine/readable_arcs.h):
// the end of the run of arcs of one site pair starting at `begin`;
std::size_t pair_run_end(const Diagram& d, std::size_t begin);
// how many times the arcs [begin, end) of one circle and the gaps between them turn around it, by
// their rounded nodes (equal angles turn 0); 1 when it is readable, -1 for a whole circle or loop
// and for circles so large against their sites (tolerance::kHugeCircleRatio) that angles cannot
// resolve their nodes: readers take those arcs as straight where they are bounded and short;
int circle_winding(const Diagram& d, std::size_t begin, std::size_t end);
// the diagonal of the sites' bounding box, and how far a point may be off a curve
// (tolerance::kSelfCheckOnCurve).
double site_extent(const std::vector<Site>& sites);
double allowed_off(double extent, double magnitude);

}  // namespace covmap::voronoi::engine
