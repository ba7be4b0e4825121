// Every fixed threshold of coverage-map cleaning (map_cleaning.h), in one place. Lengths are in
// units of the snap distance s (CleaningOptions::snap_distance, or its estimate) unless stated, so
// the cleaning behaves the same for 50 m and 500 m bins. What a user may set (the snap distance,
// the shortest chain, the preference for lines) lives in CleaningOptions. docs/CLEANING.md explains
// each choice with a picture in words.
#pragma once

#include <cstddef>

namespace covmap::cleaning::tolerance {

// --- bin size and snap distance -------------------------------------------------------------

// An edge is "axis-aligned" (a staircase step) when its smaller coordinate difference is at most
// this fraction of its length (14°): steps one bin long with both ends jittered by b/8 stay inside.
inline constexpr double kAxisAlignedSlope = 0.25;
// The map is a raster when at least this share of its edges is axis-aligned (every edge of an
// exact staircase is; a polygonized vector map has almost none).
inline constexpr double kRasterEdgeShare = 0.5;
// The bin size is the mode of the axis-aligned edge lengths: the densest window of lengths within
// this factor of each other (so a jittered 1-bin step, ±25 %, still falls in the window of b while
// 2-bin runs fall outside), then the median inside the window, re-centred three times on the
// window [m / factor, m · factor] around the estimate m.
inline constexpr double kModeWindow = 1.25;
inline constexpr int kModeRecentrings = 3;
// Estimated snap distance = this many bins: more than the gaps and overlaps of real exports (up
// to b/4) and less than one bin, so the two sides of a cell one bin wide stay apart.
inline constexpr double kSnapBins = 0.5;
// Without a raster (no bin size): this fraction of the median edge length.
inline constexpr double kSnapMedianEdges = 0.5;

// --- sampling and labelling -----------------------------------------------------------------

// Boundary samples: every ring edge is cut into pieces no longer than this (× s); a sample is
// the midpoint of a piece (never a vertex, where two edge directions compete).
inline constexpr double kSampleSpacing = 1.0;
// Rings sampled and read at once (on the threads) before their readings are combined in order:
// enough to keep the threads busy, few enough that their samples stay a small part of memory.
inline constexpr std::size_t kSampledRingsBatch = 256;
// Work and memory grow with the total boundary length over the sample spacing: more samples
// than this (a snap distance far below the map's scale) are refused rather than run out of memory.
inline constexpr double kMaxSamples = 5e7;
// A sample of cell a faces cell b when an edge of b lies within s and runs the other way: the
// cosine of the angle between the sample's edge and b's edge is at most -this (within 60° of
// antiparallel). Edges of b that merely run alongside (parallel, at a frame corner) or across
// are not the same boundary.
inline constexpr double kAntiparallelCosine = 0.5;
// ... and only where p's foot on b's edge lies within the edge, or beyond its end by at most this
// (× s): b's copy of a corner may sit a little before a's (jitter), but an edge of b that ends
// at a junction must not claim a's boundary beyond it (where a faces the outside or a third cell).
inline constexpr double kEdgeOverhang = 0.25;
// A chain's samples whose own label is something else (a flicker inside one boundary, joined
// through, map_cleaning_runs.h) look for the chain's other sensor this far (× s); also the
// largest query radius, so the edge grid's cell.
inline constexpr double kRelabelRadius = 2.0;
// Where the neighbour changes between two consecutive samples, the change is located by this
// many bisections of the stretch between them (to 1/32 of the sample spacing).
inline constexpr int kTransitionBisections = 5;
// Two copies of one boundary closer than this (× s) touch: neither a gap nor an overlap (rounding
// of both copies to the same decimals leaves ~1e-9 s).
inline constexpr double kTouching = 0.01;

// --- junctions --------------------------------------------------------------------------------

// Junction candidates (the places where a ring's neighbour changes) whose points come within
// this distance (× s) of each other are one junction.
inline constexpr double kJunctionMerge = 1.0;
// A junction moves to the least-squares meeting point of its fitted curves only when that point
// is within this distance (× s) of where the rings place it (2 bins at the default snap): nearly
// tangent curves meet far away or nowhere, and the raster's placement is better then.
inline constexpr double kNodeSnapRadius = 4.0;
// Gauss-Newton iterations for a meeting point, and the step (× s) below which it has converged.
inline constexpr int kMeetingIterations = 30;
inline constexpr double kMeetingStep = 1e-9;
// Damping of the meeting point's 2×2 normal equations, relative to their trace: with one curve
// (or parallel curves) the step is then the shortest one onto the curve(s).
inline constexpr double kMeetingDamping = 1e-9;
// At a junction on the frame, the frame counts as one more curve when the frame vertices within
// this radius (× s) lie on a line to within kFrameLineDeviation (× s): a straight stretch of the
// frame; at a frame corner it does not.
inline constexpr double kFrameLineRadius = 4.0;
inline constexpr double kFrameLineDeviation = 1.0;
// A chain's points closer to its junction than this (× s) plus the distance the junction moved
// are dropped from its ends: they were read where the rings placed the junction, and may lie
// beyond a neighbouring chain's first step from the moved junction (chains would cross).
inline constexpr double kJunctionClearance = 2.0;
// A chain whose two ends reach the same junction and that never goes farther than this (× the
// shortest chain length) from it is a sliver between candidates that were merged: dropped.
inline constexpr double kSelfLoopReach = 0.5;

// --- frame ------------------------------------------------------------------------------------

// Frame polylines are simplified (Douglas–Peucker) to this deviation (× s, one bin at the default
// snap): the staircase of an irregular frame becomes its outline (a 45° staircase's corners lie
// 0.7 bins either side of it), a rectangle its four corners.
inline constexpr double kFrameSimplify = 2.0;

// --- curve fitting ----------------------------------------------------------------------------

// Huber threshold (× s) of the robust geometric fit: chain points farther from the curve than this
// (a staircase's corners are at most ~s from the true boundary) count linearly, not squared.
inline constexpr double kHuberThreshold = 1.0;
// The orthogonal line fit (a starting value, and the line candidate) is reweighted for the Huber
// loss this many times: outliers lose their pull within two or three rounds.
inline constexpr int kLineReweightings = 5;
// Levenberg–Marquardt: iteration limit, relative cost decrease that counts as converged, and the
// initial damping relative to the normal matrix's diagonal.
inline constexpr int kFitIterations = 100;
inline constexpr double kFitCostDecrease = 1e-12;
inline constexpr double kFitInitialDamping = 1e-3;
// The damping stays within [kFitMinDamping, kFitMaxDamping] (relative to the diagonal, which is
// itself floored at kFitMinDamping for a parameter the points do not determine): a step that fails
// at 10^12 is noise, and the fit has converged.
inline constexpr double kFitMinDamping = 1e-12;
inline constexpr double kFitMaxDamping = 1e12;
// The fit works in coordinates scaled to the chain (extent 1). A circle whose curvature is below
// this (radius above 10^9 chain extents) is a line: its own sagitta is under 1e-9 of the chain.
inline constexpr double kLineCurvature = 1e-9;
// Line or circle: the line is taken when its rms per degree of freedom is within
// CleaningOptions::line_preference of the circle's, or within this fraction of the chain's extent
// of it (exact data, where both rms are rounding noise).
inline constexpr double kRmsFloor = 1e-9;
// Chains with fewer points than this are fitted by the line through their ends.
inline constexpr std::size_t kMinFitPoints = 3;

// --- range edges (range_edges.h) ---------------------------------------------------------------

// A frame vertex within this many snap distances (half a bin at the default snap) of a side of the
// map's bounding box lies on the raster's own frame, not on a reception limit.
inline constexpr double kFrameBoxReach = 1.0;
// A sensor's outside boundary is a range edge when one circle fits all its pieces off the box with
// an rms of at most this many snap distances. The simplified frame's vertices are a staircase's
// corners, within ~0.7 bins (1.4 s) of the true circle; their rms about it is ~0.4 bins (0.8 s).
inline constexpr double kRangeEdgeRms = 1.5;
// ...and the sensor's whole region lies within the circle, but for this many snap distances (the
// staircase's corners stick out of the true disc by up to ~0.7 bins).
inline constexpr double kRangeDiscSlack = 3.0;
// The raw staircase of a range edge: the sensor's ring vertices within this many snap distances of
// the circle found (its corners lie within ~0.7 bins, 1.4 s, of the true circle; the first circle
// found, of simplified corners, lies up to ~0.4 bins outside it; 3 s keeps both sides' corners).
inline constexpr double kRangeEdgeBand = 3.0;

}  // namespace covmap::cleaning::tolerance
