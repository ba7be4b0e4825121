#include "audit/map_agreement.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace covmap::audit {
namespace {


// The largest squared distance, in bins, from a bin set in `from` to the nearest bin set in `to`
// (infinity when `to` has none, 0 when `from` has none): the directed Hausdorff distance, squared.
// Meijster, Roerdink & Hesselink's exact Euclidean distance transform of `to`, evaluated only where
// `from` is set: first each bin's distance to the nearest set bin of its column, by a sweep down
// and one up over whole rows (contiguous in memory), then per row the lower envelope of the
// parabolas (i − i')² + g(i')² (Felzenszwalb & Huttenlocher). Distances are small integers, so
// every value is exact and the result does not depend on the order of the passes.
double directed_squared_distance(const std::vector<char>& from, const std::vector<char>& to, int nx, int ny) {
  const double inf = std::numeric_limits<double>::infinity();
  // Column distances; `far` (beyond any real one) marks a column without a set bin so far.
  const int far = nx + ny + 1;
  std::vector<int> g(to.size());
  for (int j = 0; j < ny; ++j) {
    const std::size_t row = static_cast<std::size_t>(j) * nx;
    for (int i = 0; i < nx; ++i)
      g[row + i] = to[row + i] ? 0 : (j > 0 ? std::min(g[row - nx + i] + 1, far) : far);
  }
  for (int j = ny - 2; j >= 0; --j) {
    const std::size_t row = static_cast<std::size_t>(j) * nx;
    for (int i = 0; i < nx; ++i) g[row + i] = std::min(g[row + i], g[row + nx + i] + 1);
  }
  double worst = 0.0;
  std::vector<double> z(nx + 1);
  std::vector<int> v(nx);
  for (int j = 0; j < ny; ++j) {
    const std::size_t row = static_cast<std::size_t>(j) * nx;
    const auto f = [&](int q) { return static_cast<double>(g[row + q]) * g[row + q]; };
    int k = -1;
    double s = 0.0;
    for (int q = 0; q < nx; ++q) {
      if (g[row + q] >= far) continue;
      while (k >= 0) {
        s = ((f(q) + q * static_cast<double>(q)) - (f(v[k]) + v[k] * static_cast<double>(v[k]))) / (2.0 * (q - v[k]));
        if (s <= z[k]) --k;
        else break;
      }
      ++k;
      v[k] = q;
      z[k] = k == 0 ? -inf : s;
      z[k + 1] = inf;
    }
    int e = 0;
    for (int q = 0; q < nx; ++q) {
      if (!from[row + q]) continue;
      if (k < 0) return inf;  // no bin of `to` at all (then no column has one)
      while (z[e + 1] < q) ++e;
      worst = std::max(worst, (q - v[e]) * static_cast<double>(q - v[e]) + f(v[e]));
    }
  }
  return worst;
}

// Bins inside the map (label != kNone there) where the labelling changes to a 4-neighbour that is
// also inside the map: the inner boundaries, without the frame.
std::vector<char> inner_boundary(const std::vector<int>& inside, std::span<const int> labels, int nx, int ny) {
  std::vector<char> b(labels.size(), 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * nx + i;
      if (inside[k] == kNone) continue;
      auto differs = [&](int ii, int jj) {
        if (ii < 0 || jj < 0 || ii >= nx || jj >= ny) return false;
        const std::size_t m = static_cast<std::size_t>(jj) * nx + ii;
        return inside[m] != kNone && labels[m] != labels[k];
      };
      b[k] = differs(i + 1, j) || differs(i - 1, j) || differs(i, j + 1) || differs(i, j - 1);
    }
  return b;
}

}  // namespace

LabelRaster rasterize_cells(std::span<const CoverageCell> cells, std::span<const int> cell_sensor,
                            const voronoi::RasterGrid& grid) {
  LabelRaster out{grid, std::vector<int>(grid.bins(), kNone)};
  // Scanline fill per polygon: every edge records where it crosses each row's centre line; per row
  // the crossings of one polygon, sorted, pair up into filled spans (even–odd over its rings).
  std::vector<std::vector<double>> crossings(static_cast<std::size_t>(grid.ny));
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (const CellPolygon& poly : cells[c].polygons) {
      for (auto& row : crossings) row.clear();
      int jmin = grid.ny, jmax = -1;
      auto add_ring = [&](const Ring& ring) {
        for (std::size_t k = 0; k < ring.size(); ++k) {
          const Point& a = ring[k];
          const Point& b = ring[(k + 1) % ring.size()];
          if (a.y == b.y) continue;
          const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
          // Rows whose centre y lies in [lo, hi).
          int j0 = static_cast<int>(std::ceil((lo - grid.y0) / grid.bin - 0.5));
          int j1 = static_cast<int>(std::ceil((hi - grid.y0) / grid.bin - 0.5)) - 1;
          j0 = std::max(j0, 0), j1 = std::min(j1, grid.ny - 1);
          for (int j = j0; j <= j1; ++j) {
            const double y = grid.center_y(j);
            if (y < lo || y >= hi) continue;
            crossings[j].push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
            jmin = std::min(jmin, j), jmax = std::max(jmax, j);
          }
        }
      };
      add_ring(poly.outer);
      for (const Ring& h : poly.holes) add_ring(h);
      for (int j = jmin; j <= jmax; ++j) {
        auto& xs = crossings[j];
        std::sort(xs.begin(), xs.end());
        for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
          // Bins whose centre x lies in [xs[k], xs[k+1]).
          const int i0 = std::max(0, static_cast<int>(std::ceil((xs[k] - grid.x0) / grid.bin - 0.5)));
          const int i1 = std::min(grid.nx - 1, static_cast<int>(std::ceil((xs[k + 1] - grid.x0) / grid.bin - 0.5)) - 1);
          for (int i = i0; i <= i1; ++i) out.labels[grid.index(i, j)] = cell_sensor[c];
        }
      }
    }
  }
  return out;
}

LabelAgreement compare_labels(const LabelRaster& map, std::span<const int> recomputed, int sensors) {
  LabelAgreement out;
  const std::size_t n = static_cast<std::size_t>(std::max(sensors, 0));
  std::vector<std::size_t> both(n, 0);
  out.map_bins.assign(n, 0);
  out.recomputed_bins.assign(n, 0);
  for (std::size_t k = 0; k < map.labels.size(); ++k) {
    const int a = map.labels[k];
    if (a == kNone) continue;
    const int b = recomputed[k];
    if (a >= 0 && static_cast<std::size_t>(a) < n) ++out.map_bins[a];
    if (b >= 0 && static_cast<std::size_t>(b) < n) ++out.recomputed_bins[b];
    if (a == b && a >= 0 && static_cast<std::size_t>(a) < n) ++both[a];
  }
  out.iou.assign(n, std::numeric_limits<double>::quiet_NaN());
  double weighted = 0.0, area = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t uni = out.map_bins[i] + out.recomputed_bins[i] - both[i];
    if (uni > 0) out.iou[i] = static_cast<double>(both[i]) / static_cast<double>(uni);
    if (out.map_bins[i] > 0) {
      weighted += out.iou[i] * static_cast<double>(out.map_bins[i]);
      area += static_cast<double>(out.map_bins[i]);
      if (out.recomputed_bins[i] == 0) out.vanished.push_back(static_cast<int>(i));
    } else if (out.recomputed_bins[i] > 0) {
      out.appeared.push_back(static_cast<int>(i));
    }
  }
  out.mean_iou = area > 0 ? weighted / area : 0.0;
  // Hausdorff distance between the inner boundaries, through distance transforms of each.
  const int nx = map.grid.nx, ny = map.grid.ny;
  const auto bm = inner_boundary(map.labels, map.labels, nx, ny);
  const auto br = inner_boundary(map.labels, recomputed, nx, ny);
  const bool any_m = std::find(bm.begin(), bm.end(), 1) != bm.end();
  const bool any_r = std::find(br.begin(), br.end(), 1) != br.end();
  const double worst = any_m && any_r ? std::max(directed_squared_distance(bm, br, nx, ny), directed_squared_distance(br, bm, nx, ny)) : 0.0;
  out.hausdorff = (any_m != any_r) ? std::numeric_limits<double>::infinity() : std::sqrt(worst) * map.grid.bin;
  return out;
}

}  // namespace covmap::audit
