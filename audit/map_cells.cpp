// The map's cells for audit(): per cleaned sensor its cells' centroid, the map's box and bin size,
// and the map rasterised for locating points in cells.
#include <algorithm>
#include <cmath>

#include "audit/audit_stages.h"

namespace covmap::audit::stages {
namespace {

// Signed area and area-weighted centroid of a ring (shoelace).
void accumulate_ring(const Ring& ring, double& area, double& cx, double& cy) {
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point& a = ring[k];
    const Point& b = ring[(k + 1) % ring.size()];
    const double cross = a.x * b.y - b.x * a.y;
    area += 0.5 * cross;
    cx += (a.x + b.x) * cross / 6.0;
    cy += (a.y + b.y) * cross / 6.0;
  }
}

}  // namespace

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

MapCells map_cells(std::span<const CoverageCell> map, const cleaning::CleanedMap& cleaned) {
  MapCells out;
  const std::size_t n = cleaned.sensors.size();
  std::unordered_map<std::string, int>& index = out.index;
  for (std::size_t i = 0; i < n; ++i) index[cleaned.sensors[i]] = static_cast<int>(i);
  // Cell areas and centroids per sensor; the map's box.
  std::vector<double>& area = out.area;
  std::vector<double>& cx = out.cx;
  std::vector<double>& cy = out.cy;
  area.assign(n, 0.0), cx.assign(n, 0.0), cy.assign(n, 0.0);
  Box& box = out.box;
  out.names.resize(n);
  for (const CoverageCell& cell : map) {
    const int s = index.count(cell.sensor) ? index[cell.sensor] : kNone;
    out.cell_sensor.push_back(s);
    // Cells of one sensor may disagree on its name; the first wins (io/coverage_map.h).
    if (s != kNone && out.names[s].empty()) out.names[s] = cell.name;
    for (const CellPolygon& p : cell.polygons) {
      for (const Point& q : p.outer) box.add(q);
      if (s == kNone) continue;
      accumulate_ring(p.outer, area[s], cx[s], cy[s]);
      for (const Ring& h : p.holes) accumulate_ring(h, area[s], cx[s], cy[s]);
    }
  }
  out.centroids.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    out.centroids[i] = area[i] != 0 ? Point{cx[i] / area[i], cy[i] / area[i]} : Point{0.5 * (box.xmin + box.xmax), 0.5 * (box.ymin + box.ymax)};
  return out;
}

double bin_size(const cleaning::CleanedMap& cleaned, const Box& box) {
  const double extent = std::hypot(box.xmax - box.xmin, box.ymax - box.ymin);
  return cleaned.report.bin_size_estimate > 0 ? cleaned.report.bin_size_estimate
                                              : std::max(cleaned.report.snap_distance, tolerance::kMinBinFraction * extent);
}

MapRaster map_raster(std::span<const CoverageCell> map, const MapCells& cells, double bin_size) {
  const Box& box = cells.box;
  double res = bin_size;
  const double bw = box.xmax - box.xmin, bh = box.ymax - box.ymin;
  if (bw * bh / (res * res) > tolerance::kMaxComparisonBins) res = std::sqrt(bw * bh / tolerance::kMaxComparisonBins);
  const voronoi::RasterGrid grid{box.xmin, box.ymin, res, std::max(1, static_cast<int>(std::ceil(bw / res))),
                                 std::max(1, static_cast<int>(std::ceil(bh / res)))};
  return MapRaster{grid, rasterize_cells(map, cells.cell_sensor, grid)};
}

int MapRaster::label_at(double x, double y) const {
  // Compared as doubles before the conversion, which is undefined beyond int's range (or for NaN).
  const double fi = std::floor((x - grid.x0) / grid.bin), fj = std::floor((y - grid.y0) / grid.bin);
  if (!(fi >= 0 && fj >= 0 && fi < grid.nx && fj < grid.ny)) return kNone;
  const int i = static_cast<int>(fi), j = static_cast<int>(fj);
  return raster.labels[grid.index(i, j)];
}

}  // namespace covmap::audit::stages
