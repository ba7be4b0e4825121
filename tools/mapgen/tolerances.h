// Every approximate comparison of the map generator, in one place.
#pragma once

namespace covmap::mapgen::tolerance {

// Received-power raster (received_power_raster.cpp): a sensor is dropped from a block of bins only
// when its upper bound on received power there is below the best lower bound (or the sensitivity)
// by more than this many dB. The bounds and the per-bin powers are each computed from the same
// few operations on values of at most a few hundred dB, so their rounding errors are below 1e-12
// dB; a slack far above that (and far below any difference that matters) makes the pruning
// discard only sensors whose computed power cannot win a bin, so labels equal brute force bit
// for bit.
inline constexpr double kPruneSlackDb = 1e-6;

}  // namespace covmap::mapgen::tolerance
