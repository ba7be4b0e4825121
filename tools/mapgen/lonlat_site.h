// covmap::mapgen::LonLatSite — a true sensor given in lon/lat (degrees) with its weight: the input
// of generate_coverage_map for geographic layouts (lonlat_sites_csv.h, town_layouts.h).
#pragma once

#include <string>

namespace covmap::mapgen {

struct LonLatSite {
  std::string id;
  double lon = 0.0;
  double lat = 0.0;
  double weight = 1.0;
  std::string name;  // a human name ("Zollikofen"), written to the map's files; may be empty
};

}  // namespace covmap::mapgen
