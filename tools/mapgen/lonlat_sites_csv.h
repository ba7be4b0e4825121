// covmap::mapgen lon/lat sensor lists: CSV with the columns id, lon, lat, weight.
//
// Accepted: a header naming id, lon, lat and weight once each, in any order and any case (extra
// columns such as population are ignored) and optionally name (the town's name, kept in
// LonLatSite::name; empty when absent), then one sensor per line; lines, delimiters (comma,
// semicolon, tab or '|'), quoting and decimal commas as io/csv_table.h reads every covmap CSV.
// This is what `node tools/mapgen/cities_sites.js --lonlat` writes.
// Guaranteed on success: at least one sensor; lon in [-180, 180], lat in (-90, 90), weight finite
// and > 0; ids non-empty and unique; no two sensors at the same lon/lat. File order kept.
// Rejected with covmap::io::InputError: unreadable file, missing or repeated header column (name
// included), and per-line problems (a line that cannot be split, missing, empty or non-numeric
// field, value out of range, duplicate id or position), all collected and reported together, each
// naming the line and the sensor id.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tools/mapgen/coverage_map_generator.h"

namespace covmap::mapgen {

struct LonLatSiteTable {
  std::vector<LonLatSite> sites;
  std::vector<int> line;  // per site, its 1-based line in the file
};

LonLatSiteTable read_lonlat_sites_csv(const std::filesystem::path& path);
// Parses text already in memory; `file` is only used in error messages.
LonLatSiteTable parse_lonlat_sites_csv(std::string_view text, const std::string& file);

}  // namespace covmap::mapgen
