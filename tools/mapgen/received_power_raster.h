// covmap::mapgen::received_power_raster — the best-server raster of any propagation model
// (propagation_model.h): each bin centre belongs to the sensor of largest received_power_dbm,
// ties to the lowest index; with a sensitivity, a bin whose largest received power is below it is
// not covered (kNone).
//
// Contract: the labels equal brute force over all sensors, bit for bit (the same
// received_power_dbm is evaluated for every sensor that is not provably beaten). Cost: the raster is
// split recursively into quarters; in each block every remaining sensor gets bounds on its received
// power over the block's bin centres —
//   path loss: P_i − 10·α_i·log10 d − γ_i·d decreases with d (α_i, γ_i ≥ 0), so it lies between its
//              values at the block's farthest and nearest distance from the sensor;
//   shadowing: |S_i| ≤ the clip limit everywhere, and about the block's centre c the unclipped
//              sum is within |∇(c)·(p − c)| + a·Σ_k (κ_k·(p − c))²/2 of its value at c (Taylor,
//              |cos''| ≤ 1); the clip is monotone, so it maps that range onto the field's;
// and sensors whose upper bound is below the best lower bound (or the sensitivity) by more than
// tolerance::kPruneSlackDb are dropped: they cannot own a bin of the block. Bins are evaluated one
// by one only over the survivors of small blocks; a block with one survivor and no sensitivity is
// filled at once. About O(bins · c + n log bins), c the survivors per small block (a few), against
// hours by brute force on large maps; shadowing costs far more per bin (16 sines and cosines per
// bound and per evaluation).
// Throws std::invalid_argument for an empty grid or a non-positive bin.
#pragma once

#include <optional>

#include "tools/mapgen/propagation_model.h"
#include "voronoi/best_server_raster.h"

namespace covmap::mapgen {

voronoi::BestServerRaster received_power_raster(const Propagation& propagation, const voronoi::RasterGrid& grid,
                                                std::optional<double> sensitivity_dbm = std::nullopt);

}  // namespace covmap::mapgen
