// Helpers of the coverage-map reader's white-box tests (coverage_map_fast_test.cpp,
// coverage_map_cells_test.cpp): maps laid out as writers lay them out, and a map or an error as
// text with every number by its bits, so that two readings compare as strings.
#pragma once

#include <nlohmann/json.hpp>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "io/coverage_map.h"
#include "io/coverage_map_drafts.h"
#include "io/input_error.h"

namespace covmap::io::testing {

using OrderedJson = nlohmann::ordered_json;

inline std::string bits(double v) {
  char text[24];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(std::bit_cast<std::uint64_t>(v)));
  return text;
}

inline void append_ring(std::string& out, const std::vector<Point>& ring) {
  out += "[";
  for (const Point& p : ring) out += bits(p.x) + "," + bits(p.y) + " ";
  out += "]";
}

// Everything a map holds, numbers by their bits, as text: equal texts mean identical maps, and a
// failure shows where they part.
inline std::string fingerprint(const CoverageMap& map) {
  std::string out = "vertices " + std::to_string(map.vertex_count) + " distortion " + bits(map.max_scale_distortion) +
                    " frame " + (map.frame ? map.frame->description() : "none") + "\n";
  for (const MapCell& cell : map.cells) {
    out += "cell " + std::to_string(cell.feature) + " sensor " + cell.sensor + " name " + cell.name + "\n";
    for (const MapPolygon& polygon : cell.polygons) {
      append_ring(out, polygon.outer);
      for (const auto& hole : polygon.holes) append_ring(out, hole);
      out += "\n";
    }
  }
  return out;
}

// The whole reader's answer: the map, or the error as the user sees it.
inline std::string outcome(const std::function<CoverageMap()>& read) {
  try {
    return fingerprint(read());
  } catch (const InputError& e) {
    return std::string("error: ") + e.what();
  }
}

// Member order as covmap-make-map, GDAL and most exporters write it: type first.
inline OrderedJson feature(OrderedJson sensor, OrderedJson geometry, std::string name = "") {
  OrderedJson properties = {{"sensor", sensor}};
  if (!name.empty()) properties["name"] = name;
  return {{"type", "Feature"}, {"properties", properties}, {"geometry", geometry}};
}

inline OrderedJson square(double x, double y, double side) {
  return OrderedJson::array({{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}, {x, y}});
}

}  // namespace covmap::io::testing
