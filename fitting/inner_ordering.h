// The groups of Ceres's inner iterations for the site refinement. Internal to fitting.
//
// Inner iterations run coordinate descent over groups of sites that share no boundary sample, so
// each group's sites can be moved independently. Left to itself, Ceres builds such groups greedily
// but breaks ties between sites of equal degree by comparing heap addresses, so one input
// converged differently from run to run (and from build to build). These groups depend on the
// input alone.
//
// Contract: rounds of pairwise independent sites (no two in a round are the two sites of one
// sample). Each round is filled greedily from the sites with the fewest neighbours among those not
// yet placed, ties broken by site index; a site is placed in exactly one round. Sites without any
// sample (sample_count 0) are in no round. Samples with site_a == site_b make no neighbours.
#pragma once

#include <span>
#include <vector>

#include "fitting/refine.h"

namespace covmap::fitting::detail {

std::vector<std::vector<int>> independent_rounds(std::size_t site_count, std::span<const BoundarySample> samples,
                                                 std::span<const int> sample_count);

}  // namespace covmap::fitting::detail
