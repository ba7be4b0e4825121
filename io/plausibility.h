// covmap::io plausibility: inputs that parse but cannot mean what they say. Each finding is a
// sentence for people; `covmap audit` refuses the input on any of them unless --force, and then
// prints them as warnings.
//
// - A map read as metres (--planar, or declaring a projected CRS) whose coordinates all lie within
//   longitude/latitude ranges and span less than kLonLatLookingSpan units: degrees read as metres
//   would make a map a few metres wide.
// - Reported sensors farther from the map's bounding box than kFarOutsideDiagonals times its
//   diagonal: a sensor there cannot serve the mapped area in any way the map could show, so it is
//   a wrong position, a wrong unit, or the wrong map. The finding says how many and how far.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/reported_sensor.h"
#include "io/coverage_map.h"

namespace covmap::io {

inline constexpr double kLonLatLookingSpan = 20.0;
inline constexpr double kFarOutsideDiagonals = 1.0;

// For a map read as metres (planar, or in a projected CRS): the finding, if its coordinates look
// like degrees. Nothing for a lon/lat map.
std::optional<std::string> lon_lat_looking(const CoverageMap& map);

// The finding, if some reported sensors lie far outside the map.
std::optional<std::string> sensors_far_outside(const CoverageMap& map, const std::vector<ReportedSensor>& sensors);

}  // namespace covmap::io
