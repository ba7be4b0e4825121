#include "audit/cell_evidence.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "voronoi/best_server_raster.h"

namespace covmap::audit::stages {
namespace {

// The window grown by `margin` bins, or by the cell's own extent if larger, clamped to the raster.
BinWindow grown(const voronoi::RasterGrid& g, BinWindow w, int margin) {
  if (w.empty()) return w;
  const int grow = std::max(margin, std::max(w.i1 - w.i0, w.j1 - w.j0));
  w.i0 = std::max(0, w.i0 - grow), w.j0 = std::max(0, w.j0 - grow);
  w.i1 = std::min(g.nx - 1, w.i1 + grow), w.j1 = std::min(g.ny - 1, w.j1 + grow);
  return w;
}

}  // namespace

void BinWindow::add(int i, int j) {
  if (empty()) {
    i0 = i1 = i, j0 = j1 = j;
    return;
  }
  i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
}

std::vector<BinWindow> cell_windows(const MapRaster& raster, std::size_t sensors) {
  const auto& g = raster.grid;
  std::vector<BinWindow> out(sensors);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int label = raster.raster.labels[g.index(i, j)];
      if (label >= 0 && static_cast<std::size_t>(label) < sensors) out[static_cast<std::size_t>(label)].add(i, j);
    }
  return out;
}

PredictedCell predicted_cell(const MapRaster& raster, const BinWindow& cell, const std::vector<Site>& sites, int sensor,
                             std::optional<double> reach, double search_radius) {
  const auto& g = raster.grid;
  // Where to look: the mapped cell and the sensor's own position, with a margin as wide as the cell
  // (a cell moved by its own size still lies inside); the whole map for a sensor without a cell.
  BinWindow w = grown(g, cell, 2);
  const Site& s = sites[static_cast<std::size_t>(sensor)];
  const double fi = std::floor((s.x - g.x0) / g.bin), fj = std::floor((s.y - g.y0) / g.bin);
  const bool inside = fi >= 0 && fj >= 0 && fi < g.nx && fj < g.ny;
  if (w.empty() && inside) {
    // A sensor without a cell that would serve bins serves those around its own position (it
    // always lies in its own cell): look within search_radius of it.
    w.add(static_cast<int>(fi), static_cast<int>(fj));
    w = grown(g, w, static_cast<int>(std::ceil(search_radius / g.bin)));
  } else if (w.empty()) {
    w = {0, 0, g.nx - 1, g.ny - 1};
  } else if (inside) {
    w.add(static_cast<int>(fi), static_cast<int>(fj));
  }
  const voronoi::RasterGrid sub{g.corner_x(w.i0), g.corner_y(w.j0), g.bin, w.i1 - w.i0 + 1, w.j1 - w.j0 + 1};
  const voronoi::BestServerRaster labels = voronoi::best_server_raster(sites, sub, reach);
  PredictedCell out;
  std::size_t both = 0;
  for (int j = 0; j < sub.ny; ++j)
    for (int i = 0; i < sub.nx; ++i) {
      const int mapped = raster.raster.labels[g.index(w.i0 + i, w.j0 + j)];
      const int predicted = labels.labels[sub.index(i, j)];
      // Outside the map (no label) counts only when the map has a reach: then it is uncovered.
      if (mapped == kNone && !reach) continue;
      out.mapped_bins += mapped == sensor;
      out.predicted_bins += predicted == sensor;
      both += mapped == sensor && predicted == sensor;
    }
  const std::size_t either = out.mapped_bins + out.predicted_bins - both;
  out.iou = either > 0 ? static_cast<double>(both) / static_cast<double>(either) : 0.0;
  return out;
}

CellDistance distance_to_cell(const MapRaster& raster, const BinWindow& cell, int sensor, Point p) {
  const auto& g = raster.grid;
  CellDistance out;
  out.host = raster.label_at(p.x, p.y);
  if (out.host == sensor) return out;
  double best = std::numeric_limits<double>::infinity();
  for (int j = cell.j0; j <= cell.j1; ++j)
    for (int i = cell.i0; i <= cell.i1; ++i) {
      if (raster.raster.labels[g.index(i, j)] != sensor) continue;
      // Distance to the bin's square.
      const double dx = std::max({g.corner_x(i) - p.x, 0.0, p.x - g.corner_x(i + 1)});
      const double dy = std::max({g.corner_y(j) - p.y, 0.0, p.y - g.corner_y(j + 1)});
      best = std::min(best, std::hypot(dx, dy));
    }
  out.metres = best;
  return out;
}

}  // namespace covmap::audit::stages
