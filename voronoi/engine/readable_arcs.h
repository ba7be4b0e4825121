// Arcs too short to be read from their rounded end nodes.
//
// Nodes are rounded once, so two nodes closer than an ulp or two (a node of degree 4 of nearly
// cocircular sites split by a perturbation of one ulp; the two crossings of nearly tangent
// bisectors) may come out equal or in the wrong order. Readers take a circle arc's sweep from its
// end nodes, so such a tiny arc would read as almost its whole circle, and a near-full arc as a
// tiny one. The walk that emits an arc knows the sites bounding its power facet (the link), so it
// can tell which piece the arc is: tiny if another crossing of its circle lies away from its
// ends; otherwise the point of the circle opposite its ends lies on the arc exactly when no link
// site is nearer there, and there the answer is not close. An arc read
// wrongly is then mended: its end nodes become one node (which is what the diagram is at the
// resolution of doubles); the tiny piece is dropped, the near-full one kept as a loop.
#pragma once

#include <vector>

#include "core/diagram.h"
#include "voronoi/engine/lifted_traits.h"

namespace covmap::voronoi::engine {

enum class ArcMend {
  kNone,     // read correctly from its nodes
  kDrop,     // a tiny arc that reads as (almost) its whole circle: merge its ends, drop it
  kLoop,     // a near-full arc that reads as tiny: merge its ends, keep it as a loop
  kUnknown,  // too close to call: the engine must fail rather than guess
};

// Whether `a` is a segment, or a circle arc (not a huge one, tolerance::kHugeCircleRatio), whose
// distinct end nodes are within rounding of each other (self_check.h's allowed_off of the sites'
// bounding-box diagonal `extent`): only such an arc may be read wrongly. Cheap; most arcs stop here.
bool ends_within_rounding(const Arc& a, const std::vector<Node>& nodes, const std::vector<Site>& sites,
                          double extent);

// For such an arc just emitted by the walk around the power facet of its sites, which found the
// zero points `zeros` (node ids in circle order) and whose other bounding sites are `link`: how
// to mend it. A segment is dropped when its rounded nodes do not follow its direction: five sites
// of a grid equidistant from one point up to the rounding of their decimal coordinates have nodes
// an ulp apart, a segment between them pointing backwards, and a face of site 8 some 1e-17 across
// that no reader can trace. The arc runs between two consecutive zeros, so if any zero of the walk
// lies farther than rounding from its ends it is the tiny piece; only when all of them cluster
// there is the point opposite probed.
ArcMend arc_mend(const Arc& a, const std::vector<Node>& nodes, const std::vector<Site>& sites,
                 const std::vector<int>& zeros, const std::vector<RawPoint>& link, double extent);

// Applies the mends (one per arc, kNone for most) to d: merges the nodes of every mended arc,
// drops kDrop arcs, keeps kLoop arcs as loops. Any other arc left between merged nodes reads
// correctly from its own (unmerged) nodes: kept as a loop if that reading is more than half its
// circle, else dropped (it was tiny too). Throws EngineFailure on kUnknown.
void apply_mends(Diagram& d, const std::vector<ArcMend>& mends);

}  // namespace covmap::voronoi::engine
