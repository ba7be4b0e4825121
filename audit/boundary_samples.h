// Points along a cleaned map's shared boundaries, for least-squares refinement: every chain between
// two sensors, and every piece of a range edge (site_b = kNone, fitting/refine.h), walked at a fixed
// spacing (one point per raster bin: neighbouring points of a
// staircase are strongly correlated, so denser sampling would only make the reported uncertainty
// too small, not the fit better).
#pragma once

#include <vector>

#include "fitting/refine.h"
#include "cleaning/map_cleaning.h"

namespace covmap::audit {

// sigma: the stated 1-σ of each point across the boundary (for a raster: bin / sqrt(12)).
// max_per_chain: a long chain gets at most this many points, spread evenly (a chain's curve has
// three parameters; beyond a few dozen points more only cost time).
std::vector<fitting::BoundarySample> sample_boundaries(const cleaning::CleanedMap& map, double spacing, double sigma,
                                                       int max_per_chain = 32);

}  // namespace covmap::audit
