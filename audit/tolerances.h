// Every fixed approximate comparison and threshold of the audit pipeline, in one place (the
// user's thresholds live in AuditOptions with their documentation).
#pragma once

#include <cstddef>

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
// Phase 1 of the refinement (weights held loosely by priors) stops earlier: it is only the start of
// phase 2, which releases those priors and lowers the cost by percents; resolving phase 1 beyond a
// part in 10⁴ of its cost changes nothing that phase 2 does not move again, and its slow tail
// would cost many iterations for nothing.
inline constexpr double kPhase1FunctionTolerance = 1e-4;
// Robust loss scale of the refinement, in sample σ (σ = bin / √12): a staircase point is at most
// ±bin/2 ≈ 1.7 σ from the true boundary, so residuals beyond 3 σ are outliers (a misassigned bin,
// a junction's corner) and weigh less.
inline constexpr double kAuditLossScale = 3.0;
// Iteration cap of the refinement's first phase: maps of 10⁴ sensors converge in far fewer; the
// cap only bounds the time of a start that does not converge.
inline constexpr int kAuditMaxIterations = 500;
// Iterations of the second refinement phase (audit/two_phase_refinement.cpp), at most.
inline constexpr int kPhase2Iterations = 60;
// Phase 2 ends earlier once the map has settled (fitting::SettleRule): when, over the last
// kPhase2SettleWindow successful iterations, no more than kPhase2MovingShare of the sensors moved by more
// than kPhase2SettledBins bins or changed their log weight by more than kPhase2SettledLogWeight.
// A twentieth of a bin and 0.01 (0.15 dB at α = 3.5) are far below what the staircases resolve
// (a sample's σ is bin/√12). The few sensors still moving then are those creeping along a flat
// valley or running off; the restart round and the local re-solves that follow are built for them,
// while every further joint iteration costs a linear solve of the whole map. On large maps many
// sensors may still move, and then Ceres' own tolerance ends phase 2.
inline constexpr int kPhase2SettleWindow = 5;
inline constexpr double kPhase2SettledBins = 0.05;
inline constexpr double kPhase2SettledLogWeight = 0.01;
inline constexpr double kPhase2MovingShare = 0.01;

// The bin size of a map that is not a raster's staircases (no bin size estimated): the cleaning's
// snap distance, but at least this fraction of the map's diagonal (a map without any snap).
inline constexpr double kMinBinFraction = 1e-6;
// The raster that compares recomputed diagrams with the map has at most this many bins; larger
// maps are compared on coarser bins (memory ~10 bytes per bin).
inline constexpr double kMaxComparisonBins = 4e6;

// Time bounds of the pipeline. Maps up to this many sensors are refined from several starts (the
// tolerant estimate, the cells' centroids, the reported sensors); larger ones from one.
inline constexpr std::size_t kMultiStartSensors = 300;
// Maps up to this many sensors get one boundary sample per bin, larger ones one per two bins.
inline constexpr std::size_t kDenseSamplingSensors = 3000;
// Rounds of restarting sensors that ended outside their own cell. A second round improves the
// agreement only slightly for twice the refinement time (docs/PERFORMANCE.md).
inline constexpr int kRestartRounds = 1;

// Seconds between progress heartbeats inside a long stage (solver iterations).
inline constexpr double kHeartbeatSeconds = 5.0;

// Judging by the cell (audit/cell_evidence.h), where the boundaries do not pin a sensor down. The
// reconstruction's own cell must overlap the mapped one by at least this (intersection over union)
// for the model to speak for the cell at all: on generated maps under the model, cells of 20 bins
// and more overlap by 0.9–1.0 (docs/ACCURACY.md), so 0.8 leaves room for small cells' staircases.
inline constexpr double kCellModelOverlap = 0.8;
// ... and the predicted cell of the values nearest the reconstruction that the report's stated
// uncertainty allows (to the χ² threshold) must overlap it as well as the reconstruction's does,
// but for the loss of moving the cell's whole boundary by one bin (sensor_audits.cpp), and by at
// least this. Those values differ
// from a right report's by its stated errors, which near equal weights can still move a small
// cell's boundary by a bin or two; a gross error of several bins, or of several dB, beyond them
// halves the overlap.
inline constexpr double kPredictedOverlap = 0.5;
// A cell of fewer bins than this (8 × 8) is below the map's resolution. The resolution condition
// of the accuracy targets (docs/ACCURACY.md), bins at most 1/10 of the local spacing, gives cells
// of ~80 bins; a smaller cell's boundaries are a few staircase steps between merged junctions,
// whose errors are correlated, so neither the χ² test of the boundary fit (it takes them as
// independent) nor the model-fit ratio applies: both flag such cells without any error. Such cells
// are judged by their cell (cell_evidence.h).
inline constexpr double kResolvedCellBins = 64.0;
// A sensor absent from the map contradicts it when its reported values would give it at least this
// many bins (a cell of a bin or two can vanish in a raster by where its bin centres fall).
inline constexpr std::size_t kMinPredictedBins = 4;
// ... and its predicted cell is looked for within this many mean sensor spacings of its reported
// position: a cell reaching farther still covers bins within it, which is all the test needs.
inline constexpr double kPredictionSearchSpacings = 4.0;

// A sensor with a range edge whose boundaries the fit draws this many times worse (mean square)
// than free curves has no range edge there (audit_stages.h, drop_unfitted_range_edges): the model
// fit's own test and default (AuditOptions::model_misfit_ratio); a true range edge is drawn as
// well by both, while a hole's Apollonius circle, fitted as a reach, pulls the sensor off.
inline constexpr double kRangeEdgeMisfitRatio = 4.0;

// Local re-solves (audit/local_resolve.cpp) run only while at most this share of the sensors is
// suspect: on maps drawn by the model a minority are; on maps the model does not explain most are,
// and the re-solves, which cannot fix a model, would take nearly all of the audit's time.
inline constexpr double kLocalMaxSuspectShare = 0.5;

// Model fit (audit/model_fit.h). The map's own noise is at least this many bins (rms), however
// well a free curve happens to fit a boundary: a boundary drawn exactly (no staircase) would
// otherwise make any model residual, even rounding, look like a misfit.
inline constexpr double kMisfitNoiseFloorBins = 0.1;
// The map as a whole does not follow the model when more than this share of its area lies in
// misfit sensors (a few misfit cells are local: terrain, an obstacle; a tenth of the map is not).
inline constexpr double kMisfitAreaShare = 0.1;
// A sensor's model-fit ratio is measured only over at least this many boundary samples (about one
// per bin): a cell a few bins across is below the map's resolution, and a mean square of a handful
// of staircase steps varies by factors of several by chance, even under the model itself.
inline constexpr int kMisfitMinSamples = 20;
// ... and only for cells of at least kResolvedCellBins.
// The reports against the map (audit/model_fit.h, ModelFit (2)). Where the model holds and the
// reports are right, a sensor's χ² tail probability is uniform or larger (the floors only shrink
// χ²): the median over its neighbours is below 0.1 only when more than half of them carry gross
// errors (with 10 % of sensors wrong and six neighbours, P ≈ 1.6 %); maps drawn by other models
// fall far below it (docs/ACCURACY.md).
inline constexpr double kMisfitPValue = 0.1;
// ... over at least this many judged neighbours (a sensor with fewer is judged alone).
inline constexpr std::size_t kMisfitMinNeighbours = 4;
// The map-level median needs at least this many judged sensors.
inline constexpr std::size_t kMisfitMinJudged = 10;

}  // namespace covmap::audit::tolerance

// ---- Local re-solves of badly placed sensors (audit/local_resolve.cpp) ----
namespace covmap::audit::tolerance {
// A sensor one of whose boundaries (with one neighbour) has a median residual above this many
// sample σ (σ = bin / √12) fits poorly and is solved again locally: a correctly placed sensor's
// staircase residuals are uniform within ±bin/2, median |r| = bin/4 ≈ 0.87 σ; at 2 σ that boundary
// is on average more than half a bin off. Only boundaries of at least kLocalMinBoundarySamples
// samples count (a median of fewer is noise, and a junction's corner dominates a short one).
inline constexpr double kLocalPoorFitSigma = 2.0;
inline constexpr std::size_t kLocalMinBoundarySamples = 5;
// Two neighbouring sites closer than this many bins are suspected of having merged (one of them
// drawn onto the other, their bisector a circle of a radius set by two tiny differences); both are
// solved again. True neighbours that close exist, and a re-solve leaves them where they are.
inline constexpr double kLocalMergedBins = 0.5;
// A site counts as inside its own cell when the comparison raster's bin holding it, or one of the
// eight around it at this many raster bins, is the cell's: the raster is coarser than the map's
// own bins on the largest maps and a site may lie within a bin of its cell's edge (a heavy sensor
// beside a light neighbour's small cell).
inline constexpr double kLocalCellSlackBins = 1.0;
// A local re-solve that leaves two sites closer than this many bins has merged them (no raster
// tells sites that close apart, and at one point they have no diagram): it is not accepted.
inline constexpr double kLocalCoincidentBins = 1e-3;
// A site outside the map counts as in its own cell within this many mean sensor spacings of the
// cell's centroid (a sensor beyond the map's edge), as for the restarts.
inline constexpr double kLocalOutsideMapSpacings = 3.0;
// The sensors held around a local re-solve: position priors of this many bins and log-weight
// priors of this σ. Tight enough that the held sensors move by a negligible fraction of a bin (a
// hundred samples at 1 σ pull one by ~10⁻³ bin), loose enough to keep the solve well conditioned.
inline constexpr double kLocalHeldPositionBins = 1e-3;
inline constexpr double kLocalHeldLogWeight = 1e-4;
// The sensors within this many steps (shared boundaries) of a re-solved sensor are free in its
// local solve. One ring cannot undo a merged pair's distortion of the sensors around it (the ring
// held at the distorted values keeps the sensor bins off); two can, and three cost more time for
// no better result.
inline constexpr std::size_t kLocalFreeRings = 2;
// A candidate start within this many bins of the current site or of another candidate descends to
// the same minimum (a local minimum's basin is several bins wide) and is not solved again.
inline constexpr double kLocalSameStartBins = 2.0;
// An island host is a suspect only when its boundaries with its other neighbours could hide a move
// of this many bins (σ·√n, local_resolve.cpp): the inverse-point ambiguity of an island's circle
// moves the host by several bins (docs/ACCURACY.md), and a local minimum's
// basin is kLocalSameStartBins wide.
inline constexpr double kLocalIslandHostHiddenBins = 2.0;
// Iteration cap of one local re-solve (a few dozen sensors; most converge in far fewer).
inline constexpr int kLocalMaxIterations = 50;

// The path-loss exponent the map and the reported powers imply (alpha_estimate.h). Fewer sensors
// with a reported power and a cell than this, or a spread of their powers below
// kAlphaMinPowerSpreadDb, leave alpha undetermined: the slope of log weight against power needs
// several points across a range of powers.
inline constexpr std::size_t kAlphaMinSensors = 5;
inline constexpr double kAlphaMinPowerSpreadDb = 3.0;
// Sensors whose residual from the robust line exceeds this many robust standard deviations (1.4826
// MAD) are gross errors, left out of the final fit: a power reported 6 dB off is one point off
// the line, not evidence about alpha.
inline constexpr double kAlphaOutlierSigmas = 3.0;
// A given --alpha farther than this many σ from the estimate, and by more than this fraction of it,
// is named as disagreeing with the data. The fraction keeps a near-exact map (σ of a few 10⁻³) from
// calling 3.4 against 3.5 wrong: the warning is for a wrong alpha (a typo, another environment),
// and 5 % of alpha moves a 20 dB power difference by 1 dB, the precision powers are reported at.
inline constexpr double kAlphaDisagreementSigmas = 3.0;
inline constexpr double kAlphaDisagreementFraction = 0.05;
// At most this many pairs enter the median of pairwise slopes (Theil–Sen); beyond that the pairs
// are taken at a fixed stride, so the estimate stays linear-time and reproducible.
inline constexpr std::size_t kAlphaMaxPairs = 200'000;
}  // namespace covmap::audit::tolerance
