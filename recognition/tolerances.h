// Every fixed approximate comparison of the recognition library, in one place. (Tolerances a user
// may set — relative_tolerance, matrix_tolerance, weight_snap, the comparison's horizon — live in
// RecognitionOptions and CompareOptions with their documentation.)
#pragma once

namespace covmap::recognition::tolerance {

// An arc's end node may be off its curve by the recognition tolerance plus this many units of
// rounding (machine epsilon times |c| + r + |v| for a circle with centre c and radius r, |v| + |p|
// for a line through p): the three numbers are each rounded once, and huge circles (nearly equal
// weights) carry absolute errors ~ε·r that no tolerance relative to the graph's extent absorbs.
inline constexpr double kArcEndRoundingUlps = 16.0;

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
