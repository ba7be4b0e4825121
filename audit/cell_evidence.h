// What a sensor's mapped cell says about its report, apart from the boundary fit.
// Internal to the audit library.
//
// Two facts of the model need no boundary fit:
//   - every sensor lies in its own cell (d(p, s)/w = 0 at p = s), so a reported position inside
//     another sensor's mapped cell is off by at least its distance from its own cell;
//   - the reported position and power, put among the refined sensors, predict a cell; the map's
//     cell either is that cell (up to the map's noise) or is not.
// The audit uses them where the boundaries do not pin a sensor down (a cell cut by the frame with
// one neighbour, a small cell in a dense cluster) and for sensors reported but absent from the map
// (is their predicted cell empty, as the map says?).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "audit/audit_stages.h"

namespace covmap::audit::stages {

// The bins of each map sensor's cell in the comparison raster, as an inclusive window of bin
// indices (empty when the sensor has no bin): one pass over the raster for every later question.
struct BinWindow {
  int i0 = 0, j0 = 0, i1 = -1, j1 = -1;
  void add(int i, int j);
  bool empty() const { return i1 < i0; }
};
std::vector<BinWindow> cell_windows(const MapRaster& raster, std::size_t sensors);

// Bins are the comparison raster's (MapRaster); counts are of bins inside the map.
struct PredictedCell {
  std::size_t mapped_bins = 0;     // the sensor's bins in the map
  std::size_t predicted_bins = 0;  // bins the sensor wins with the values tried
  double iou = 0.0;                // |mapped ∩ predicted| / |mapped ∪ predicted| (0 when both empty)
};

// Sensor `sensor` of `sites` (index; may be one past the map's sensors, for a sensor absent from
// the map) at its values in `sites`, the others as they are; reach: the reception limit R for
// weight 1, when the map has one (then uncovered bins inside the map's box count as the map's
// "nobody", which a predicted cell must not cover either).
// `cell`: the sensor's window (cell_windows; empty for a sensor without a cell, which is then looked
// for within `search_radius` of its position, or over the whole map when it lies outside it).
PredictedCell predicted_cell(const MapRaster& raster, const BinWindow& cell, const std::vector<Site>& sites, int sensor,
                             std::optional<double> reach, double search_radius = 0.0);

// Distance from p to the nearest bin of `sensor` in the map (0 when p lies in one; +inf when the
// sensor has no bin), and the sensor whose cell holds p (kNone: uncovered or outside the map).
struct CellDistance {
  double metres = 0.0;
  int host = kNone;
};
CellDistance distance_to_cell(const MapRaster& raster, const BinWindow& cell, int sensor, Point p);

}  // namespace covmap::audit::stages
