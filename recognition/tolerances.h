// Every fixed approximate comparison of the recognition library, in one place. (Tolerances a user
// may set — relative_tolerance, matrix_tolerance, weight_snap, the comparison's horizon — live in
// RecognitionOptions and CompareOptions with their documentation.)
#pragma once

#include <cstddef>

namespace covmap::recognition::tolerance {

// Two solution circles whose intersection discriminant is negative by less than this fraction of
// the terms' size are taken as tangent (one common point): the discriminant of a true tangency
// comes out of rounding as ±1e-16 of them.
inline constexpr double kTangentDiscriminant = 1e-12;

// An arc's end node may be off its curve by the recognition tolerance plus this many units of
// rounding (machine epsilon times |c| + r + |v| for a circle with centre c and radius r, |v| + |p|
// for a line through p): the three numbers are each rounded once, and huge circles (nearly equal
// weights) carry absolute errors ~ε·r that no tolerance relative to the graph's extent absorbs.
inline constexpr double kArcEndRoundingUlps = 16.0;

// Gauss-Newton polishing stops when the solution circles' normal equations are this close to
// singular (all circles nearly parallel at the point): a step would then be noise.
inline constexpr double kSingularNormalEquations = 1e-12;

// Two lines are the same direction (compare_graphs) / run the same way (graph repair) when the
// sine, respectively 1 − cosine, of their angle is below these. Directions of bisector lines come
// from rounded site differences (errors ~1e-16); distinct real bisectors differ by far more.
inline constexpr double kSameDirectionSine = 1e-9;
inline constexpr double kSameDirectionCosine = 1e-12;

// Degree-2 repair in `covmap recognize`: two arcs are on one curve when their centres, radii or
// line offsets agree to this fraction of the graph's coordinate magnitude (double rounding of the
// numbers that state a curve).
inline constexpr double kRepairRelative = 1e-12;

// feasible_region: how many of the facets where the paraboloid leaves the lifted polyhedron are
// probed for a representative point. Each probe costs O(m); any one probe already yields a valid
// point, more only a deeper one.
inline constexpr std::size_t kMaxProbedFacets = 64;
// ... and the shortest step (a fraction of the search window's half-size) tried from a boundary
// point into the region: regions thinner than this are reported as having no interior.
inline constexpr double kSmallestProbeStep = 1e-9;
// A facet whose unit normal has a t-component below this fraction of its (x, y) part is vertical: it
// meets the paraboloid in a line (a line constraint or a side of the window; the normal of an
// exactly vertical facet, computed from its rounded vertices, is ~1e-17 off).
inline constexpr double kVerticalFacet = 1e-14;

// Starting values for noisy maps (tolerant_sites.h). A junction's solution circle whose curvature
// is below this fraction of its normalised linear term is a line; it is kept as a circle of that
// curvature (radius ~1e9 frame lengths), which the least-squares intersection handles as a line.
inline constexpr double kEstimateLineCurvature = 1e-9;
// Going around an even-degree junction is the identity (no constraint) when the composed matrix's
// off-diagonal entry c is below this fraction of its largest entry.
inline constexpr double kEstimateIdentity = 1e-9;
// Tie-breaker between candidate positions with (nearly) equal residuals, e.g. the two
// intersections of two circles: a pull of this weight (per unit squared length) towards the
// sensor's own cell, far too weak to move a well-determined estimate.
inline constexpr double kEstimateCentroidPull = 1e-6;
// Added to the log-weight system's diagonal to fix each connected component's free common factor.
inline constexpr double kEstimateGaugePull = 1e-6;

// The audit's first refinement phase holds every log weight loosely about its start: ±3 is a
// factor of 20, far looser than any boundary constrains a weight, but it stops a weight that a
// poor start leaves unconstrained from running off (recognition/audit.cpp, phase 2 drops it).
inline constexpr double kAuditLogWeightPrior = 3.0;

// A refined sensor whose log weight differs from the median of its neighbours' by more than this
// (a factor of 100) has diverged and is restarted (recognition/audit.cpp). Real neighbours differ
// by a few dB; a factor of 100 is 70 dB at a path-loss exponent of 3.5.
inline constexpr double kAuditMaxLogWeightJump = 4.6;

// Gauss–Newton of a starting estimate stops when a step is below this fraction of the position's
// magnitude (rounding level; the estimate only has to be a good start).
inline constexpr double kEstimateStepStop = 1e-12;
// A sensor's 3×3 information block (local_uncertainty.h) is singular when its smallest eigenvalue
// is below this fraction of its largest: the sensor is then reported undetermined.
inline constexpr double kLocalInformationConditioning = 1e-12;
// The audit's refinement stops when an iteration lowers the cost by less than this fraction: the
// cost sums thousands of staircase points whose noise is ±bin/2, and a smaller change moves no
// sensor by a measurable fraction of a bin.
inline constexpr double kAuditFunctionTolerance = 1e-7;

}  // namespace covmap::recognition::tolerance
