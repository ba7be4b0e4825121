// The second pass of the coverage-map reader (internal to io/): each usable feature's
// polygons projected into the map's plane and validated there (io/coverage_map_rings.h), on all
// cores.
//
// Features are independent here: a feature's cell, its vertex count, its worst point scale and its
// problems depend on nothing but the feature and the projection. So each feature is one item of
// core/parallel.h's parallel_items, writing only its own slot, and the slots are combined in
// feature order afterwards: the cells, the counts, the distortion (a maximum, the same in any
// order) and the problems are identical for every worker count.
#pragma once

#include <cstddef>
#include <vector>

#include "io/coverage_map.h"
#include "io/coverage_map_drafts.h"
#include "io/local_projection.h"

namespace covmap::io::detail {

// Appends to `map` a cell for every usable draft (in draft order), adds their kept vertices to
// map.vertex_count and, when `local` is set (lon/lat input), raises map.max_scale_distortion to the
// worst |k / k_centre - 1| over their projected vertices; appends each draft's geometry problems to
// its own `problems`. Positions are used as they are without `local`. The drafts' positions are
// released as they are used. `workers` threads at most (1: all on the calling thread). An exception
// in any feature (out of memory) is rethrown here, the first in feature order.
void add_cells(std::vector<FeatureDraft>& drafts, const LocalProjection* local, CoverageMap& map, int workers);

// The worker count add_cells is given for a map of `vertices` positions: the machine's cores once
// the work outweighs starting threads (core/parallel.h worker_count, counted in vertices).
int cell_workers(std::size_t vertices);

}  // namespace covmap::io::detail
