// The last steps of map cleaning: junctions moved onto their fitted curves, frame polylines
// simplified, and the arc graph. Internal to map_cleaning.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "cleaning/map_cleaning.h"

namespace covmap::cleaning {

// Moves every junction to the least-squares meeting point of the curves fitted to its chains (and
// of the frame, where the frame is straight around it), when that point lies within
// kNodeSnapRadius · snap. `chains` hold their interior points only (no junction at either end).
// Returns how many junctions moved.
std::size_t refine_junctions(std::vector<Point>& junctions, const std::vector<BoundaryChain>& chains,
                             double snap);

// Every non-loop chain's points made to run from its junction to its junction (map.junctions,
// after refine_junctions; `raw` are the junctions before): points closer to a junction than
// kJunctionClearance · snap plus the distance it moved are dropped first (they may lie beyond a
// neighbouring chain's first step from the moved junction). Frame chains are then simplified.
// Returns the number of frame chains.
std::size_t finish_chains(CleanedMap& map, const std::vector<Point>& raw, double snap);

// Douglas–Peucker to `tolerance`, keeping both ends (open) or at least a triangle (closed).
std::vector<Point> simplify_open(std::span<const Point> points, double tolerance);
std::vector<Point> simplify_closed(std::span<const Point> points, double tolerance);

// map.chains (points now with their junctions at both ends, frame chains simplified) and
// map.junctions → map.graph nodes and arcs, map.arc_chain. Non-frame arcs lie on their chain's
// curve refitted through the arc's end nodes (fit_through), so every arc ends exactly on its curve.
// graph.sites must already hold one site per sensor. threads: for the refits (the graph is the
// same whatever the count).
void build_graph(CleanedMap& map, double snap, double huber, int threads = 1);

}  // namespace covmap::cleaning
