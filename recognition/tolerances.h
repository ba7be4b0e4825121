// Every fixed approximate comparison of the recognition library, in one place. (Tolerances a user
// may set — relative_tolerance, weight_snap, the comparison's horizon — live in
// RecognitionOptions and CompareOptions with their documentation.)
#pragma once

#include <cstddef>

namespace covmap::recognition::tolerance {

// An arc's end node may be off its curve by the recognition tolerance plus this many units of
// rounding (machine epsilon times |c| + r + |v| for a circle with centre c and radius r, |v| + |p|
// for a line through p): the three numbers are each rounded once, and huge circles (nearly equal
// weights) carry absolute errors ~ε·r that no tolerance relative to the graph's extent absorbs.
inline constexpr double kArcEndRoundingUlps = 16.0;

// The graph frame (graph_frame.cpp) is centred on the graph when the middle of its extent is more
// than this many extents from the origin; nearer, centring would gain less than a bit.
inline constexpr double kFrameTranslation = 2.0;

// The graph's extent is at most this many times the box of the middle half of its nodes (graphs
// with more than 2 % of their nodes far out: input_preparation.cpp). For well-spread nodes the
// central 98 % box is about twice the middle half's, so this changes nothing there.
inline constexpr double kMiddleHalfFactor = 8.0;

// An extent whose diagonal is below this fraction of the coordinates' size has collapsed to one
// point (every node at the centre of cocircular equal-weight sites, up to rounding): it fixes no
// length, and the coordinates' size stands in for it.
inline constexpr double kCollapsedExtent = 1e-6;

// The matrix tolerance of a node (RecognitionOptions::relative_tolerance in the node's frame) is
// never below kMatrixRounding — the rounding of composing up to a few dozen 2×2 complex products
// with O(1) entries — and never above kMatrixCeiling, beyond which "proportional" and "identity"
// would lose their meaning (a node much shorter than the tolerance).
inline constexpr double kMatrixRounding = 1e-12;

// A node's frame (node_constraint.cpp) is the median length of its arcs, leaving out arcs shorter
// than this fraction of the graph's extent: the pieces of a point where four or more bisectors meet,
// split by rounding into nodes 1e-17..1e-10 apart, whose length says nothing about the distance of
// the sites. (A frame that small read every solution circle as its tangent line.)
inline constexpr double kNodeFrameFloor = 1e-9;
inline constexpr double kMatrixCeiling = 1e-2;

// The weight solve (weight_solve.cpp): an arc's statement of log(w_r / w_l) weighs
// (|c - s_l|² + |c - s_r|²) over the graph's mean site spacing squared, between 1 and kMaxArcWeight
// (lines, and huge circles of nearly equal weights, are the most accurate; a larger spread would
// only slow the conjugate gradients, and without the floor of 1 short arcs count for too little
// and the solution is worse).
inline constexpr double kMaxArcWeight = 1e4;
// The weight and position solves' conjugate gradients stop when the preconditioned residual has
// shrunk by kSolveReduction (the position solve's start is within ~1e-10 of the answer, so this is
// well below rounding), or below its own rounding (weights), or after kSolveIterations passes over
// the arcs — a safety net that neither reaches even on the largest graphs: the position solve's
// mirror relations fix every site (no null space) and converge fast under Jacobi; the weight
// solve's Laplacian, preconditioned by multigrid, stays well below it even from a start spoilt by
// a wrong arc (weight_solve.cpp).
inline constexpr double kSolveReduction = 1e-8;
inline constexpr int kSolveIterations = 100;
// The weight solve's multigrid (laplacian_multigrid.h) coarsens until at most kCoarsestUnknowns
// remain, which it factors densely (a few MB of work at most), and gives up coarsening when a level
// keeps more than kCoarsening of its unknowns (a graph whose matching fails, such as a star; planar
// graphs keep about a fifth).
inline constexpr std::size_t kCoarsestUnknowns = 256;
inline constexpr double kCoarsening = 0.75;
// The multigrid's K-cycle makes a second Krylov step on a level only while the first left more than
// this fraction of the residual (the value of Notay's aggregation multigrid).
inline constexpr double kKCycleResidual = 0.25;
// The position solve makes at most kPositionSteps Gauss-Newton steps, a further one only while the
// last moved a site by more than kFurtherStep of the extent — a rounded graph, where the
// linearisation error of a correction c (~c²) still matters; an exact graph's first correction is
// ~1e-12 — and none whose correction exceeds kLinearisation of the extent (the linearised mirror
// relations would not hold; the propagated sites are kept and verification judges them).
inline constexpr int kPositionSteps = 3;
inline constexpr double kFurtherStep = 1e-10;
inline constexpr double kLinearisation = 1e-1;

// A node's solution circle whose curvature, in the node's frame, is below this fraction of its
// linear term is its tangent line: radii beyond 1e9 frame units are rounding of a line (the
// composition's entries are exact to ~1e-15), and keeping them as circles would make forms with
// entries ~1e18 in plane coordinates.
inline constexpr double kSolutionLine = 1e-9;

// Gauss-Newton polishing stops when the solution circles' normal equations are this close to
// singular (all circles nearly parallel at the point): a step would then be noise.
inline constexpr double kSingularNormalEquations = 1e-12;

// The MWVD check (mwvd_check.h) allows a difference of weighted distances at a point what the
// reconstruction's uncertainty makes of it (RecognitionOptions::relative_tolerance) plus this many
// units of rounding of the numbers that state the point (machine epsilon times |p|, and |c| + r
// for a point computed on a circle with centre c and radius r), over the sites' weights: the input
// states its nodes and curves to the last bit at best, and points on huge circles (nearly equal
// weights) carry absolute errors ~ε·r.
inline constexpr double kPointRoundingUlps = 16.0;

// Two lines are the same direction (compare_graphs) / run the same way (graph repair) when the
// sine, respectively 1 − cosine, of their angle is below these. Directions of bisector lines come
// from rounded site differences (errors ~1e-16); distinct real bisectors differ by far more.
inline constexpr double kSameDirectionSine = 1e-9;
inline constexpr double kSameDirectionCosine = 1e-12;

// Degree-2 repair of input graphs (prepare_input_graph): two arcs are on one curve when their centres, radii or
// line offsets agree to this fraction of the graph's coordinate magnitude (double rounding of the
// numbers that state a curve).
inline constexpr double kRepairRelative = 1e-12;

}  // namespace covmap::recognition::tolerance
