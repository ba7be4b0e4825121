// Every fixed approximate comparison and threshold of the audit pipeline, in one place (the
// user's thresholds live in AuditOptions with their documentation).
#pragma once

namespace covmap::audit::tolerance {

// Starting values for noisy maps (start_values.h). A junction's solution circle whose curvature
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
// poor start leaves unconstrained from running off (audit/two_phase_refinement.cpp, phase 2
// drops it).
inline constexpr double kAuditLogWeightPrior = 3.0;

// A refined sensor whose log weight differs from the median of its neighbours' by more than this
// (a factor of 100) has diverged and is restarted (audit/multi_start_refinement.cpp). Real
// neighbours differ by a few dB; a factor of 100 is 70 dB at a path-loss exponent of 3.5.
inline constexpr double kAuditMaxLogWeightJump = 4.6;

// Gauss–Newton of a starting estimate stops when a step is below this fraction of the position's
// magnitude (rounding level; the estimate only has to be a good start).
inline constexpr double kEstimateStepStop = 1e-12;
// The audit's refinement stops when an iteration lowers the cost by less than this fraction: the
// cost sums thousands of staircase points whose noise is ±bin/2, and a smaller change moves no
// sensor by a measurable fraction of a bin.
inline constexpr double kAuditFunctionTolerance = 1e-7;

}  // namespace covmap::audit::tolerance
