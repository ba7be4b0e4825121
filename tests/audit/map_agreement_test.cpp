// audit::rasterize_cells and audit::compare_labels against values computed by hand on small
// rasters (rectangles, half-planes shifted by k bins) and against brute force (point in polygon
// per bin centre, intersection over union by counting, Hausdorff distance over all pairs of
// boundary bins).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "audit/map_agreement.h"
#include "core/point_in_polygon.h"

namespace covmap::audit {
namespace {

Ring rectangle(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

CoverageCell cell(std::vector<CellPolygon> polygons) {
  CoverageCell c;
  c.polygons = std::move(polygons);
  return c;
}

// Brute force: every bin centre tested against every cell; a later cell overrides an earlier one.
std::vector<int> brute_force_labels(const std::vector<CoverageCell>& cells, const std::vector<int>& sensor,
                                    const voronoi::RasterGrid& g) {
  std::vector<int> labels(g.bins(), kNone);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Point p{g.center_x(i), g.center_y(j)};
      for (std::size_t c = 0; c < cells.size(); ++c)
        for (const CellPolygon& poly : cells[c].polygons)
          if (inside_polygon(poly, p)) labels[g.index(i, j)] = sensor[c];
    }
  return labels;
}

TEST(MapAgreement, RectangleOnBinEdgesFillsExactlyItsBins) {
  const voronoi::RasterGrid g{0.0, 0.0, 1.0, 10, 8};
  const std::vector<CoverageCell> cells{cell({{rectangle(2, 1, 7, 5), {}}})};
  const LabelRaster r = rasterize_cells(cells, std::vector<int>{3}, g);
  ASSERT_EQ(r.labels.size(), 80u);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 10; ++i) {
      const bool in = i >= 2 && i <= 6 && j >= 1 && j <= 4;
      EXPECT_EQ(r.labels[g.index(i, j)], in ? 3 : kNone) << i << "," << j;
    }
}

TEST(MapAgreement, OffsetGridAndBinSize) {
  // Bins of 2 m from (-3, 10): the rectangle [1, 9) × [14, 20) covers the bins whose centres
  // x = -2 + 2i and y = 11 + 2j lie inside: i = 2..5 (x = 2, 4, 6, 8), j = 2..4 (y = 15, 17, 19).
  const voronoi::RasterGrid g{-3.0, 10.0, 2.0, 8, 6};
  const std::vector<CoverageCell> cells{cell({{rectangle(1, 14, 9, 20), {}}})};
  const LabelRaster r = rasterize_cells(cells, std::vector<int>{0}, g);
  int count = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const bool in = i >= 2 && i <= 5 && j >= 2 && j <= 4;
      EXPECT_EQ(r.labels[g.index(i, j)], in ? 0 : kNone) << i << "," << j;
      count += in;
    }
  EXPECT_EQ(count, 12);
}

TEST(MapAgreement, HolesOverlapsAndPiecesAsBruteForce) {
  const voronoi::RasterGrid g{0.0, 0.0, 0.5, 40, 30};
  CellPolygon ring_with_hole{rectangle(1.1, 1.3, 12.7, 13.9), {{{4.2, 4.1}, {4.4, 9.3}, {9.6, 8.8}, {8.1, 4.6}}}};
  CellPolygon triangle{{{13.3, 0.7}, {19.4, 2.2}, {15.1, 14.2}}, {}};
  CellPolygon small{rectangle(15.6, 8.3, 19.1, 14.6), {}};  // overlaps the triangle
  CellPolygon plug{{{5.3, 5.7}, {7.9, 5.2}, {7.2, 7.7}}, {}};  // inside the hole
  const std::vector<CoverageCell> cells{cell({ring_with_hole}), cell({triangle, plug}), cell({small})};
  const std::vector<int> sensor{0, 1, 2};
  const LabelRaster r = rasterize_cells(cells, sensor, g);
  const std::vector<int> expect = brute_force_labels(cells, sensor, g);
  ASSERT_EQ(r.labels.size(), expect.size());
  int mismatches = 0, in_hole = 0, plugged = 0, overlap_to_later = 0;
  for (std::size_t k = 0; k < expect.size(); ++k) mismatches += r.labels[k] != expect[k];
  EXPECT_EQ(mismatches, 0);
  // The brute force really exercised what it should: bins in the hole that are not plugged, bins
  // of the plug, bins where the later cell won.
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Point p{g.center_x(i), g.center_y(j)};
      const int l = r.labels[g.index(i, j)];
      if (inside_ring(ring_with_hole.holes[0], p) && !inside_ring(plug.outer, p)) {
        ++in_hole;
        EXPECT_EQ(l, kNone);
      }
      if (inside_ring(plug.outer, p)) {
        ++plugged;
        EXPECT_EQ(l, 1);
      }
      if (inside_ring(triangle.outer, p) && inside_ring(small.outer, p)) {
        ++overlap_to_later;
        EXPECT_EQ(l, 2);
      }
    }
  EXPECT_GT(in_hole, 20);
  EXPECT_GT(plugged, 5);
  EXPECT_GT(overlap_to_later, 2);
}

// Two half-planes: sensor 0 west of column `split`, sensor 1 east of it, on an nx × ny grid.
std::vector<int> half_planes(int nx, int ny, int split) {
  std::vector<int> l(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) l[static_cast<std::size_t>(j) * nx + i] = i < split ? 0 : 1;
  return l;
}

TEST(MapAgreement, HalfPlanesShiftedByKBins) {
  const int nx = 20, ny = 10, m = 10;
  const double bin = 2.5;
  LabelRaster map{{0.0, 0.0, bin, nx, ny}, half_planes(nx, ny, m)};
  for (int k = 0; k <= 9; ++k) {
    const LabelAgreement a = compare_labels(map, half_planes(nx, ny, m + k), 2);
    // Sensor 0: map m·ny bins, recomputed (m+k)·ny, all of the map's inside the recomputed one.
    ASSERT_EQ(a.iou.size(), 2u);
    EXPECT_EQ(a.map_bins[0], static_cast<std::size_t>(m * ny));
    EXPECT_EQ(a.recomputed_bins[0], static_cast<std::size_t>((m + k) * ny));
    EXPECT_EQ(a.recomputed_bins[1], static_cast<std::size_t>((nx - m - k) * ny));
    const double iou0 = static_cast<double>(m) / (m + k);
    const double iou1 = static_cast<double>(nx - m - k) / (nx - m);
    EXPECT_NEAR(a.iou[0], iou0, 1e-15) << k;
    EXPECT_NEAR(a.iou[1], iou1, 1e-15) << k;
    // Both cells have m·ny map bins: the area-weighted mean is the plain mean.
    EXPECT_NEAR(a.mean_iou, 0.5 * (iou0 + iou1), 1e-15) << k;
    // Boundary columns m−1, m against m+k−1, m+k: k bins apart.
    EXPECT_NEAR(a.hausdorff, k * bin, 1e-12) << k;
    EXPECT_TRUE(a.vanished.empty());
    EXPECT_TRUE(a.appeared.empty());
  }
}

TEST(MapAgreement, MeanIsWeightedByMapArea) {
  // Map: sensor 0 in columns 0..2 (30 bins), sensor 1 in 3..9 (70 bins); recomputed: split at 5.
  // IoU0 = 30/50, IoU1 = 50/70, mean = (30·0.6 + 70·5/7) / 100 = 0.68.
  const int nx = 10, ny = 10;
  LabelRaster map{{0.0, 0.0, 1.0, nx, ny}, half_planes(nx, ny, 3)};
  const LabelAgreement a = compare_labels(map, half_planes(nx, ny, 5), 2);
  EXPECT_NEAR(a.iou[0], 0.6, 1e-15);
  EXPECT_NEAR(a.iou[1], 5.0 / 7.0, 1e-15);
  EXPECT_NEAR(a.mean_iou, 0.68, 1e-15);
}

TEST(MapAgreement, VanishedAppearedAndOutsideTheMap) {
  // 6 × 4 grid; the map's last column is outside (kNone). Map: sensor 0 in columns 0..1, sensor 1
  // in 2..4. Recomputed: sensor 0 in columns 0..1, sensor 2 (absent from the map) in 2..3, sensor 3
  // only outside the map (column 5), sensor 1 nowhere.
  const int nx = 6, ny = 4;
  std::vector<int> m(nx * ny), rec(nx * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      m[j * nx + i] = i < 2 ? 0 : i < 5 ? 1 : kNone;
      rec[j * nx + i] = i < 2 ? 0 : i < 4 ? 2 : i < 5 ? kNone : 3;
    }
  const LabelAgreement a = compare_labels(LabelRaster{{0, 0, 1, nx, ny}, m}, rec, 5);
  ASSERT_EQ(a.iou.size(), 5u);
  EXPECT_DOUBLE_EQ(a.iou[0], 1.0);
  EXPECT_DOUBLE_EQ(a.iou[1], 0.0);
  EXPECT_DOUBLE_EQ(a.iou[2], 0.0);  // 8 recomputed bins, none in its (empty) map cell
  EXPECT_TRUE(std::isnan(a.iou[3])) << "only outside the map: neither";
  EXPECT_TRUE(std::isnan(a.iou[4]));
  EXPECT_EQ(a.recomputed_bins[3], 0u) << "bins outside the map are not counted";
  EXPECT_EQ(a.vanished, std::vector<int>{1});
  EXPECT_EQ(a.appeared, std::vector<int>{2});
  // Weighted by map area: (8·1 + 12·0) / 20.
  EXPECT_NEAR(a.mean_iou, 0.4, 1e-15);
}

TEST(MapAgreement, HausdorffIsInfiniteWhenOnlyOneSideHasABoundary) {
  const int nx = 8, ny = 5;
  LabelRaster map{{0, 0, 1, nx, ny}, half_planes(nx, ny, 4)};
  const std::vector<int> uniform(nx * ny, 0);
  EXPECT_TRUE(std::isinf(compare_labels(map, uniform, 2).hausdorff));
  LabelRaster one_cell{{0, 0, 1, nx, ny}, uniform};
  EXPECT_EQ(compare_labels(one_cell, uniform, 2).hausdorff, 0.0) << "no boundary on either side";
}

// The inner boundary of a labelling as compare_labels defines it: bins inside the map with a
// 4-neighbour inside the map labelled differently.
std::vector<std::pair<int, int>> boundary_bins(const std::vector<int>& inside, const std::vector<int>& labels, int nx,
                                               int ny) {
  std::vector<std::pair<int, int>> out;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (inside[k] == kNone) continue;
      const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
      for (int e = 0; e < 4; ++e) {
        const int ii = i + di[e], jj = j + dj[e];
        if (ii < 0 || jj < 0 || ii >= nx || jj >= ny) continue;
        const int m = jj * nx + ii;
        if (inside[m] != kNone && labels[m] != labels[k]) {
          out.push_back({i, j});
          break;
        }
      }
    }
  return out;
}

double directed(const std::vector<std::pair<int, int>>& from, const std::vector<std::pair<int, int>>& to) {
  double worst = 0.0;
  for (auto [i, j] : from) {
    double best = std::numeric_limits<double>::infinity();
    for (auto [p, q] : to) best = std::min(best, std::hypot(i - p, j - q));
    worst = std::max(worst, best);
  }
  return worst;
}

// Nearest-seed labellings: the map's seeds and the recomputed ones (moved), some bins outside.
std::vector<int> seed_labels(const std::vector<Point>& seeds, int nx, int ny) {
  std::vector<int> l(nx * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      int best = 0;
      for (std::size_t s = 1; s < seeds.size(); ++s)
        if (std::hypot(i - seeds[s].x, j - seeds[s].y) < std::hypot(i - seeds[best].x, j - seeds[best].y))
          best = static_cast<int>(s);
      l[j * nx + i] = best;
    }
  return l;
}

TEST(MapAgreement, RandomLabellingsAgainstBruteForce) {
  const int nx = 37, ny = 29, sensors = 6;
  const double bin = 1.7;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> ux(0, nx), uy(0, ny), jitter(-4, 4);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<Point> seeds(sensors), moved(sensors);
    for (int s = 0; s < sensors; ++s) {
      seeds[s] = {ux(rng), uy(rng)};
      moved[s] = {seeds[s].x + jitter(rng), seeds[s].y + jitter(rng)};
    }
    std::vector<int> m = seed_labels(seeds, nx, ny);
    const std::vector<int> rec = seed_labels(moved, nx, ny);
    // A disc outside the map.
    const double cx = ux(rng), cy = uy(rng);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        if (std::hypot(i - cx, j - cy) < 6) m[j * nx + i] = kNone;
    const LabelAgreement a = compare_labels(LabelRaster{{0, 0, bin, nx, ny}, m}, rec, sensors);
    double weighted = 0, area = 0;
    for (int s = 0; s < sensors; ++s) {
      std::size_t in_map = 0, in_rec = 0, both = 0;
      for (std::size_t k = 0; k < m.size(); ++k) {
        if (m[k] == kNone) continue;
        in_map += m[k] == s, in_rec += rec[k] == s, both += m[k] == s && rec[k] == s;
      }
      EXPECT_EQ(a.map_bins[s], in_map);
      EXPECT_EQ(a.recomputed_bins[s], in_rec);
      const std::size_t uni = in_map + in_rec - both;
      if (uni == 0) {
        EXPECT_TRUE(std::isnan(a.iou[s]));
        continue;
      }
      EXPECT_NEAR(a.iou[s], static_cast<double>(both) / uni, 1e-15);
      weighted += static_cast<double>(both) / uni * in_map, area += in_map;
    }
    EXPECT_NEAR(a.mean_iou, weighted / area, 1e-14);
    const auto bm = boundary_bins(m, m, nx, ny), br = boundary_bins(m, rec, nx, ny);
    ASSERT_FALSE(bm.empty());
    ASSERT_FALSE(br.empty());
    const double h = std::max(directed(bm, br), directed(br, bm)) * bin;
    EXPECT_NEAR(a.hausdorff, h, 1e-12 * (1 + h)) << "trial " << trial;
  }
}

}  // namespace
}  // namespace covmap::audit
