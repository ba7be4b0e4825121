// The rings of a coverage map as map cleaning reads them, and the map's scale (bin size, snap
// distance). Internal to map_cleaning.
//
// Contract: collect_rings accepts any cells (rings of fewer than 3 distinct vertices or of zero
// area are skipped; consecutive repeated vertices dropped). Every returned ring has its cell on the
// left: outer rings counter-clockwise, holes clockwise, reversed when given the other way. Sensors
// are numbered in order of first appearance. estimate_bin_size returns the mode of the
// axis-aligned edge lengths, or 0 when the rings are not a raster's staircases
// (map_cleaning_tolerances.h says when).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "core/coverage_cells.h"
#include "core/diagram.h"

namespace covmap::cleaning {

struct BoundaryRing {
  int sensor = kNone;       // index into MapRings::sensors
  int cell = 0;                      // index of the input cell
  std::vector<Point> points;  // implicitly closed, the sensor's area on the left
  std::vector<double> arc;           // arc length at each vertex; arc.back() = perimeter (n + 1 entries)

  std::size_t size() const { return points.size(); }
  double perimeter() const { return arc.back(); }
  // The point at arc length s (taken modulo the perimeter) and the edge it lies on (at a vertex:
  // the edge that starts there).
  Point at(double s, std::size_t* edge = nullptr) const;
};

struct MapRings {
  std::vector<std::string> sensors;
  std::vector<BoundaryRing> rings;
  std::size_t input_vertices = 0;
  std::size_t cells = 0;  // cells with at least one polygon
};

MapRings collect_rings(std::span<const CoverageCell> cells);

double estimate_bin_size(const std::vector<BoundaryRing>& rings);
double median_edge_length(const std::vector<BoundaryRing>& rings);

// Twice the signed area (positive counter-clockwise) of an implicitly closed polygon.
double twice_signed_area(const std::vector<Point>& ring);

}  // namespace covmap::cleaning
