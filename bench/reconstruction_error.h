// How far a reconstruction is from the sites that drew the graph: for the benchmarks of
// recognition (recognition_bench --verify, mwvd_check_bench).
#pragma once

#include <utility>
#include <vector>

#include "core/diagram.h"
#include "recognition/recognize.h"

namespace covmap::bench {

// Every reconstructed site against the nearest original one (found through a grid over the
// originals' bounding box): the largest distance relative to the box's larger side, and the largest
// relative difference of weights normalised to a largest of 1 (the heaviest site always owns a
// face, so both sets share it). Infinite when there is nothing to match.
std::pair<double, double> reconstruction_error(const std::vector<Site>& truth, const recognition::Reconstruction& r);

}  // namespace covmap::bench
