// covmap::mapgen site layouts: spacing of a sensor layout, and random layouts for tests and demos.
//
// mean_nearest_neighbour_distance: the mean, over sites, of the distance to the closest other site.
// Needs at least two sites (std::invalid_argument otherwise). Sort-and-sweep, O(n log n) for
// well-spread sites.
//
// random_sites: `count` sites uniform in the rectangle [-width/2, width/2] × [-height/2, height/2]
// (metres, centred on the origin so a lon/lat centre lands in the middle), weights log-uniform in
// [1/weight_ratio, 1], ids "r0001", "r0002", ... Deterministic for a seed on every platform
// (RandomStream). Rejects (std::invalid_argument) count < 1, non-positive sizes, weight_ratio < 1.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/diagram.h"

namespace covmap::mapgen {

double mean_nearest_neighbour_distance(std::span<const Site> sites);

struct RandomSitesOptions {
  int count = 100;             // number of sites
  double width_m = 50'000.0;   // east-west size of the area
  double height_m = 50'000.0;  // north-south size of the area
  double weight_ratio = 4.0;   // largest / smallest possible weight (1: all weights equal)
  std::uint64_t seed = 1;
};

std::vector<Site> random_sites(const RandomSitesOptions& options);

}  // namespace covmap::mapgen
