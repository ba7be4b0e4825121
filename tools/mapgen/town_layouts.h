// covmap::mapgen town layouts: clustered sensor layouts cut from a list of real towns.
//
// clustered_town_sites picks, from the seed, one town of the list uniformly at random (the window's
// centre) and returns the `count` towns nearest to it — a compact region of a real settlement
// pattern: dense towns a few hundred metres apart next to sparse countryside. Nearness is measured
// on a local equirectangular plane about the centre town (Δlon·cos(lat0), Δlat, with Δlon taken
// across the antimeridian when shorter), ties to the earlier town in the list; the towns are
// returned in list order with their ids and lon/lat unchanged.
// Weights:
//   kPopulation    the list's weight column unchanged (cities_sites.js writes (population /
//                  min-population)^(1/4); the generator rescales so the strongest has weight 1).
//   kPowerClasses  tx-power classes as a planner assigns them: the towns are ranked by their local
//                  spacing (distance to the nearest other chosen town, on the same plane) and split
//                  into as many equal groups as classes; the most isolated group gets the highest
//                  power (a macro site in the countryside), the densest the lowest (small cells in
//                  town). weight = 10^((P_class − P_max) / (10·alpha)).
// Deterministic for a seed on every platform (RandomStream, purpose kTownLayout). Rejects
// (std::invalid_argument) count < 2 or larger than the list, an empty or non-finite class list,
// non-positive alpha.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tools/mapgen/lonlat_site.h"

namespace covmap::mapgen {

enum class TownWeights { kPopulation, kPowerClasses };

// "population", "power-classes".
std::string_view to_string(TownWeights weights);
std::optional<TownWeights> town_weights_from_string(std::string_view text);

struct TownLayoutOptions {
  int count = 100;                                       // towns in the window
  TownWeights weights = TownWeights::kPopulation;
  std::vector<double> power_classes_dbm = {43.0, 37.0, 31.0};  // kPowerClasses: macro, micro, small cell
  double alpha = 3.5;                                    // kPowerClasses: exponent turning powers into weights
  std::uint64_t seed = 1;
};

struct TownWindow {
  std::vector<LonLatSite> sites;  // the chosen towns, in list order, with their layout weights
  std::size_t centre = 0;         // index in the list of the window's centre town
};

// Where a map's true sensors came from, for truth.json (set by whoever cut the window).
struct TownLayoutRecord {
  std::string towns_file;         // the town list as named by the user
  std::size_t towns_in_file = 0;
  std::string centre_town;        // id of the window's centre town
  TownWeights weights = TownWeights::kPopulation;
  std::vector<double> power_classes_dbm;  // kPowerClasses only
};

TownWindow clustered_town_sites(std::span<const LonLatSite> towns, const TownLayoutOptions& options);

}  // namespace covmap::mapgen
