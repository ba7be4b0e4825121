// Every approximate comparison made outside the exact engine core, in one place.
//
// The engine's combinatorics (which sites meet, in which order, where degrees exceed three) are
// exact and use no tolerance (engine/exact_sign.h documents its filters' error bounds). The
// algorithms below work on rounded output coordinates and need these:
#pragma once

namespace covmap::voronoi::tolerance {

// Face tracing: two arcs leaving a node (or two unbounded arcs) whose directions differ by less
// than this angle (radians) are taken as tangent (parallel) and ordered by curvature (by offset at
// infinity). Tangencies are real in degenerate input (collinear sites: circles tangent to a line
// at a node), but a tangency node is a double root, known only to ~√ε ≈ 1e-8 relative, so its
// tangent directions carry errors up to ~1e-9 rad. For arcs that do not cross, the curvature (or
// offset) order is the true order whenever the angle difference is this small.
// Departure directions are compared as pseudo-angles (continuations.cpp, slope 1/2 to 1 per radian), so
// the threshold acts as 1 to 2 times this many radians: the same order of magnitude, which is all
// a bound on rounding needs.
inline constexpr double kParallelAngle = 1e-8;

// Face tracing by geometry, placing holes: a hole's containing face is read off the first arc hit
// by a ray to +x from the hole's rightmost point. Two hits closer than kRayTie times the size of the
// numbers they are computed from are one point (the ray passes through a node: ambiguous), and a hit where the arc's
// tangent has a y-component below kRayTangent grazes it; both fall back to containment tests,
// which are slower but decide by area, so these only need to exceed rounding.
inline constexpr double kRayTie = 1e-12;
inline constexpr double kRayTangent = 1e-12;

// Face tracing, cycle orientation (cycle_orientation.cpp): a cycle's signed area within this many
// ulps of the size of the terms it is summed from has no sign to trust (a lens between nodes an ulp
// apart); its orientation is then its total turning, read from directions.
inline constexpr double kOrientationAreaUlps = 64.0;

// Clipping: a crossing of an arc with the clip boundary closer than this fraction of the clip
// polygon's size (the diagonal of its bounding box) to a polygon vertex is snapped onto that vertex, so an arc through a corner
// is not split into a piece of zero length.
inline constexpr double kClipSnap = 1e-12;
// Not a tolerance but a limit: clipping tests every arc and every node against every polygon
// edge, so its work is (arcs + nodes) × polygon vertices. Beyond this many such tests (a few
// minutes) clip_diagram refuses with ClipTooLarge rather than run for hours: 10^5 arcs (and their
// nodes) against a 20 000-vertex polygon is allowed, 10^4 sites against a 10^6-vertex polygon is not.
inline constexpr double kMaxClipWork = 4e9;

// Engine: root nodes of different triangulation facets closer than this fraction of the sites'
// extent are *candidates* for being one node (facets whose lifted sites are coplanar and
// co-circular share one power line, hence its crossings). Whether they are merged is decided by
// exact predicates, never by this distance; it only needs to exceed the nodes' rounding error.
inline constexpr double kNodeMergeCandidate = 1e-9;

// Engine, node construction (engine/triple_node.h): a node's coefficients are evaluated in doubles
// with a running error bound and used when the node error that bound implies is below this
// fraction of the sites' extent (plus 4 ulps of the node); otherwise they are evaluated exactly
// and rounded once. Not a decision threshold (the node is the same root either way) but an
// accuracy budget, 1000 times below the self-check's kSelfCheckOnCurve. Most nodes near the sites
// pass; nearly tangent bisectors, nearly collinear lifted sites and far nodes take the exact path.
inline constexpr double kNodeError = 1e-12;

// Engine self-check (engine/self_check.h): an arc end node may lie this fraction of the sites'
// extent off its arc's curve, plus kSelfCheckUlps units in the last place of the largest magnitude
// involved (the node's coordinates, the curve's centre and radius), which no double can state more
// precisely. Nodes are constructed to within kNodeError of the extent, so a node beyond this is
// wrong, not rounded; the bound is 100 times tighter than the independent checker's default
// (1e-7 of the extent, 64 ulps), so what passes here passes there.
inline constexpr double kSelfCheckOnCurve = 1e-9;
inline constexpr double kSelfCheckUlps = 64.0;

// Engine: an Apollonius circle whose radius exceeds this many times its sites' distance (weights
// equal to ~6 digits or more) is "huge": its centre and radius are only known to a few ulps of
// its size, so bounded arcs on it whose sagitta is below that are written as straight lines, and
// the angles of its nodes seen from its centre do not resolve them (the self-check does not order
// its arcs by angle).
inline constexpr double kHugeCircleRatio = 1e6;

// Engine, arcs whose end nodes round to one point (engine/readable_arcs.h): whether such an
// arc is its circle's tiny or near-full piece is read at the point opposite its node, where the
// arc's own sites are nearest (near-full) or another site is (tiny). The weighted distances there
// are computed to ~1e-15 relative; a difference below this fraction is too close to call and the
// engine fails loudly instead of guessing. Away from other degeneracies the difference there is of
// the order of the circle's size.
inline constexpr double kPieceProbeMargin = 1e-12;

// Best-server raster: a site is dropped from a block of bins only when its smallest possible
// weighted distance to the block exceeds the block's upper bound (or the maximum range) by more
// than this relative amount. Each bound and each per-bin distance sqrt(dx² + dy²) / w is computed
// with a relative error below 4 units in the last place (≈ 9e-16), so four of them compose to well
// under 1e-14; a slack of 1e-12 therefore never drops the site that the per-bin evaluation would
// have chosen, and costs nothing measurable (a site this close to the bound is kept one level
// longer). The labels themselves are decided by exact comparisons of the computed distances.
inline constexpr double kPruneRelativeSlack = 1e-12;

}  // namespace covmap::voronoi::tolerance
