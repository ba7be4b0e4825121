#include "voronoi/best_server_raster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "voronoi/tolerances.h"

namespace covmap::voronoi {
namespace {


// The ownership distance of the contract, in one place so every caller computes the same bits.
inline double weighted_distance(double px, double py, const Site& s) {
  const double dx = px - s.x;
  const double dy = py - s.y;
  return std::sqrt(dx * dx + dy * dy) / s.weight;
}

// Blocks of at most this many bins are evaluated bin by bin over their candidates: below it,
// splitting further costs more in bounds than it saves in distance evaluations.
constexpr long kLeafBins = 64;

class Labeller {
 public:
  Labeller(std::span<const Site> sites, const RasterGrid& grid, std::optional<double> range, std::vector<int>& labels)
      : sites_(sites), grid_(grid), range_(range), labels_(labels) {}

  void run() {
    std::vector<int> all(sites_.size());
    for (std::size_t k = 0; k < sites_.size(); ++k) all[k] = static_cast<int>(k);
    block(0, grid_.nx - 1, 0, grid_.ny - 1, all);
  }

 private:
  // Bins i0..i1 × j0..j1 (inclusive); `candidates` in ascending index order contains every site
  // that can own a bin of the block.
  void block(int i0, int i1, int j0, int j1, const std::vector<int>& candidates) {
    // The block's bin centres, computed by the same expressions as the per-bin evaluation, so the
    // rectangle holds exactly the points evaluated.
    const double xlo = grid_.center_x(i0), xhi = grid_.center_x(i1);
    const double ylo = grid_.center_y(j0), yhi = grid_.center_y(j1);

    // Upper bound on the best distance anywhere in the block: the smallest, over candidates, of
    // the distance to the block's farthest corner.
    double upper = std::numeric_limits<double>::infinity();
    for (const int k : candidates) {
      const Site& s = sites_[k];
      const double dx = std::max(std::abs(s.x - xlo), std::abs(s.x - xhi));
      const double dy = std::max(std::abs(s.y - ylo), std::abs(s.y - yhi));
      upper = std::min(upper, std::sqrt(dx * dx + dy * dy) / s.weight);
    }
    double keep_below = upper * (1.0 + tolerance::kPruneRelativeSlack);
    if (range_) keep_below = std::min(keep_below, *range_ * (1.0 + tolerance::kPruneRelativeSlack));

    std::vector<int> kept;
    kept.reserve(candidates.size());
    for (const int k : candidates) {
      const Site& s = sites_[k];
      const double dx = std::max({xlo - s.x, 0.0, s.x - xhi});
      const double dy = std::max({ylo - s.y, 0.0, s.y - yhi});
      if (std::sqrt(dx * dx + dy * dy) / s.weight <= keep_below) kept.push_back(k);
    }

    if (kept.empty()) return;  // every bin is out of range: labels stay kNone
    if (kept.size() == 1 && !range_) {
      for (int j = j0; j <= j1; ++j)
        std::fill_n(labels_.begin() + static_cast<std::ptrdiff_t>(grid_.index(i0, j)), i1 - i0 + 1, kept[0]);
      return;
    }
    const long width = i1 - i0 + 1, height = j1 - j0 + 1;
    if (kept.size() == 1 || width * height <= kLeafBins) {
      per_bin(i0, i1, j0, j1, kept);
      return;
    }
    if (width >= height) {
      const int mid = i0 + static_cast<int>(width / 2) - 1;
      block(i0, mid, j0, j1, kept);
      block(mid + 1, i1, j0, j1, kept);
    } else {
      const int mid = j0 + static_cast<int>(height / 2) - 1;
      block(i0, i1, j0, mid, kept);
      block(i0, i1, mid + 1, j1, kept);
    }
  }

  void per_bin(int i0, int i1, int j0, int j1, const std::vector<int>& kept) {
    for (int j = j0; j <= j1; ++j) {
      const double py = grid_.center_y(j);
      for (int i = i0; i <= i1; ++i) {
        const double px = grid_.center_x(i);
        int best = kNone;
        double best_d = std::numeric_limits<double>::infinity();
        for (const int k : kept) {  // ascending: strict < keeps the lowest index on ties
          const double d = weighted_distance(px, py, sites_[k]);
          if (d < best_d) {
            best_d = d;
            best = k;
          }
        }
        if (range_ && best_d > *range_) best = kNone;
        labels_[grid_.index(i, j)] = best;
      }
    }
  }

  std::span<const Site> sites_;
  const RasterGrid& grid_;
  std::optional<double> range_;
  std::vector<int>& labels_;
};

}  // namespace

BestServerRaster best_server_raster(std::span<const Site> sites, const RasterGrid& grid,
                                    std::optional<double> max_weighted_range) {
  if (grid.nx < 1 || grid.ny < 1) throw std::invalid_argument("best_server_raster: the grid has no bins");
  if (!(grid.bin > 0.0) || !std::isfinite(grid.bin)) throw std::invalid_argument("best_server_raster: bin size must be positive");
  if (max_weighted_range && !(*max_weighted_range >= 0.0))
    throw std::invalid_argument("best_server_raster: the maximum range must be >= 0");
  BestServerRaster out;
  out.grid = grid;
  out.labels.assign(grid.bins(), kNone);
  if (!sites.empty()) Labeller(sites, grid, max_weighted_range, out.labels).run();
  return out;
}

}  // namespace covmap::voronoi
