// How well a recomputed diagram reproduces a coverage map, measured on a raster of the map's area:
// each bin centre gets the map's sensor (by point in polygon, even–odd over the cells' rings) and
// the recomputed sensor (weighted nearest site, voronoi/best_server_raster.h). Areas are counted in
// bins, so the answer is exact up to the raster's resolution, which the caller chooses (the map's
// own bin size where there is one).
#pragma once

#include <limits>
#include <span>
#include <vector>

#include "core/coverage_cells.h"
#include "voronoi/best_server_raster.h"

namespace covmap::audit {

struct LabelRaster {
  voronoi::RasterGrid grid;
  std::vector<int> labels;  // per bin: sensor index or kNone (outside the map)
};

// cell_sensor[k]: the sensor index of cells[k]. A bin covered by two cells (an overlap) keeps the
// later cell's sensor.
LabelRaster rasterize_cells(std::span<const CoverageCell> cells, std::span<const int> cell_sensor,
                            const voronoi::RasterGrid& grid);

struct LabelAgreement {
  // Per sensor index (size = number of sensors): |map ∩ recomputed| / |map ∪ recomputed| in bins,
  // NaN when the sensor has neither.
  std::vector<double> iou;
  std::vector<std::size_t> map_bins, recomputed_bins;
  double mean_iou = 0.0;   // area-weighted over the map's cells
  double hausdorff = 0.0;  // between the two rasters' inner boundaries, in map units
  std::vector<int> vanished;  // sensors with map bins but none recomputed inside the map
  std::vector<int> appeared;  // sensors with recomputed bins inside the map but none in the map
};

// recomputed: per bin of map.grid, the recomputed sensor index (< sensors) or kNone.
LabelAgreement compare_labels(const LabelRaster& map, std::span<const int> recomputed, int sensors);

}  // namespace covmap::audit
