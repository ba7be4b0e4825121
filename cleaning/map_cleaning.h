// cleaning::clean_coverage_map — from a coverage map's polygons (staircases of raster
// bins, rounded, with small gaps and overlaps between cells) to an arc graph that recognition and
// fitting can use: the boundaries shared by two cells, the junctions where three or more cells
// meet, the map's outer frame, and a circle or line fitted to every shared boundary.
//
// Contract:
//   Input: cells in planar coordinates (metres), as read by io/coverage_map.h. Several cells may
//   name the same sensor (pieces of one region); cells of one sensor are one region here.
//   Output (CleanedMap):
//   - sensors: the distinct sensor ids, in order of first appearance; every index below refers to
//     this list.
//   - chains: maximal boundary pieces between exactly two sensors (a, b with a < b), or between one
//     sensor and the outside of the map (b = kNone: a frame chain). Each chain is an ordered
//     polyline through the cleaned boundary, from one junction to another, or a closed loop
//     (from = to = kNone, e.g. an island cell). Chains never cross each other.
//   - junctions: points where three or more sensors meet, or where a shared boundary reaches the
//     frame; close-together junction candidates (within the snap distance) are merged into one.
//   - for every non-frame chain, the fitted bisector: the circle (or line, when a line fits as well
//     within the fit tolerance) that best fits the chain's points in the geometric least-squares
//     sense, with its rms and max deviation. Frame chains are not fitted (kept as polylines).
//   - graph: a Diagram with one node per junction and one arc per chain: non-frame chains
//     as arcs of their fitted circle/line between their junction nodes (node positions snapped to
//     the intersection of the fitted curves where they nearly meet; an arc's endpoints lie on its
//     curve), frame chains as frame arcs (straight segments between consecutive frame vertices, so
//     a frame arc is a Line arc between two nodes; frame vertices that are not junctions become
//     nodes of degree 2 between frame arcs). left_site / right_site hold sensor indices (kNone
//     outside the frame). arc_chain maps arcs to chains.
//     Details: a non-frame arc's curve is its chain's fit refitted through the arc's two end
//     nodes (the line through them, or the best circle of the family through them), so its ends
//     lie on it exactly; chain.fit stays the free fit. A chain whose two ends are one junction
//     (a loop through it) becomes two arcs with a degree-2 node at its far point. graph.sites has
//     one placeholder site per sensor (its id at the area centroid of its cells, weight 1:
//     recognition estimates the real ones); graph.faces is left empty (recognition traces faces
//     by geometry).
//   - range_edges: the parts of frame chains where a sensor's coverage ends at a reception limit
//     (a circle about the sensor) rather than at the map's frame, per sensor with its circle.
//   - report: what was repaired and how often (every repair counted), and the bin size estimate.
//   Guaranteed: deterministic; O(V log V + L / s) for V polygon vertices, boundary length L and
//   snap distance s (the boundaries are sampled every s).
//   Rejected with std::invalid_argument: an empty map (no cell with a usable ring), options out
//   of range (negative or non-finite lengths, line_preference < 1), and a snap distance so small
//   against the boundaries' length that sampling them would take more than 5·10^7 samples.
//   Everything else is repaired and counted. docs/CLEANING.md describes every repair and tolerance.
//
// Why chains are found from vertices rather than by exact shared edges: exports round and jitter
// coordinates, so two cells' copies of one boundary differ by up to the snap distance, with gaps
// (no cell) and overlaps (two cells) between them. A boundary point of cell a that has cell b
// within the snap distance (and no third cell) lies on the a|b boundary.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/coverage_cells.h"
#include "core/diagram.h"

namespace covmap::cleaning {

// Thrown when the snap distance is so small against the map that cleaning would need more than
// tolerance::kMaxSamples boundary samples (the work grows with perimeter / snap).
class SnapTooSmall : public std::invalid_argument {
 public:
  SnapTooSmall(double snap, double perimeter);
  double snap = 0.0;       // map units
  double perimeter = 0.0;  // of all rings, map units
};

struct CleaningOptions {
  // How far apart two cells' copies of one boundary may lie (gaps, overlaps, rounding), in map
  // units. 0: estimated from the map (a small multiple of the typical staircase step).
  double snap_distance = 0.0;
  // A chain shorter than this many snap distances is too short to fit a curve to; it is merged
  // into its junction (counted as a repair).
  double min_chain_length = 4.0;
  // A line is preferred over a circle when its rms is within this factor of the circle's.
  double line_preference = 1.05;
  // Threads for indexing, sampling and reading the rings and for fitting the chains and arcs (the
  // result is the same whatever the count). >= 1.
  int threads = 1;
};

struct FittedCurve {
  Curve curve;      // circle or line in map units
  double rms = 0.0;          // rms geometric distance of the chain's points to the curve
  double max_deviation = 0.0;
};

struct BoundaryChain {
  int sensor_a = kNone;   // a < b; b = kNone for a frame chain
  int sensor_b = kNone;
  int from = kNone;       // junction indices, kNone for a closed loop
  int to = kNone;
  // Ordered along the chain, a on the left of travel. Non-loop chains start and end at their
  // junctions' positions; non-frame chains' other points are midpoints between the two cells'
  // copies of the boundary (those within ~1 bin of a junction dropped), frame chains' are the
  // simplified frame's vertices.
  std::vector<Point> points;
  // Non-frame chains only: fitted to the chain's boundary points (before the junctions were
  // added and the points next to them dropped). Lines run along the chain.
  FittedCurve fit;
};

// Where a sensor's coverage ends at a reception limit (range_edges.h says how these are told from
// the map's frame): pieces of its frame chains and the circle fitted to all of them.
struct RangeEdge {
  int sensor = kNone;
  std::vector<std::vector<Point>> pieces;  // polylines, the sensor on the left
  FittedCurve fit;                         // a circle about (near) the sensor
};

struct CleaningReport {
  double snap_distance = 0.0;      // used (given or estimated)
  double bin_size_estimate = 0.0;  // typical staircase step of the boundaries (0 if not a raster)
  std::size_t input_vertices = 0;
  std::size_t cells = 0;
  std::size_t sensors = 0;
  std::size_t chains = 0;
  std::size_t frame_chains = 0;
  std::size_t range_edges = 0;     // sensors whose coverage ends at a reception limit somewhere
  std::size_t junctions = 0;
  std::size_t junctions_merged = 0;     // junction candidates merged into a neighbour
  std::size_t gaps_closed = 0;          // boundary stretches where the two cells did not touch
  std::size_t overlaps_resolved = 0;    // boundary stretches where the two cells overlapped
  std::size_t short_chains_dropped = 0;
  std::size_t nodes_snapped = 0;        // nodes moved onto the meeting point of fitted curves
  std::size_t seams = 0;  // stretches where two pieces of one sensor's region touch (no boundary;
                          // counted once from each piece)
};

struct CleanedMap {
  std::vector<std::string> sensors;
  std::vector<BoundaryChain> chains;
  std::vector<Point> junctions;
  Diagram graph;
  std::vector<int> arc_chain;  // per arc of graph: the chain it came from
  std::vector<RangeEdge> range_edges;  // at most one per sensor, in sensor order
  CleaningReport report;
};

CleanedMap clean_coverage_map(std::span<const CoverageCell> cells, const CleaningOptions& options = {});

}  // namespace covmap::cleaning
