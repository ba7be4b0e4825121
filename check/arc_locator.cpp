#include "check/arc_locator.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace covmap::check::detail {
namespace {

// floor(v) as a cell number in [0, n): clamped while still a double, since converting a double
// beyond int's range (or NaN) to int is undefined behaviour.
int cell_index(double v, int n) {
  const double f = std::floor(v);
  return !(f > 0) ? 0 : f >= n - 1 ? n - 1 : static_cast<int>(f);
}

constexpr int kMaxCellsPerSide = 1024;
constexpr double kMaxChunksPerArc = 1e6;  // a guard only: clipped arcs are a few box sizes long
}  // namespace

ArcLocator::ArcLocator(const std::vector<std::optional<ArcPath>>& paths, const Box& box,
                       const std::vector<double>& reach) {
  int used = 0;
  double widest = 0.0;
  for (std::size_t a = 0; a < paths.size(); ++a)
    if (paths[a]) {
      ++used;
      widest = std::max(widest, reach[a]);
    }
  box_ = box.grown(widest);
  // About one cell per arc, so a cell lists a handful of arcs.
  const double w = box_.xmax - box_.xmin, h = box_.ymax - box_.ymin;
  const int side =
      std::clamp(static_cast<int>(std::ceil(std::sqrt(std::max(used, 1)))), 1, kMaxCellsPerSide);
  cell_ = std::max(w, h) / side;
  if (!(cell_ > 0.0)) cell_ = 1.0;
  nx_ = std::max(1, static_cast<int>(std::ceil(w / cell_)));
  ny_ = std::max(1, static_cast<int>(std::ceil(h / cell_)));

  std::vector<std::pair<int, int>> entries;  // (cell, arc)
  for (int a = 0; a < static_cast<int>(paths.size()); ++a) {
    if (!paths[a]) continue;
    const ArcPath& path = *paths[a];
    for (const auto& [lo, hi] : clip_to_box(path, box_)) {
      const double length = (hi - lo) * path.speed();
      const double chunks =
          std::min(std::max(1.0, std::ceil(length / (0.5 * cell_))), kMaxChunksPerArc);
      const double step = (hi - lo) / chunks;
      // Off-chord bulge of a circle chunk: r (1 - cos(step / 2)) = 2 r sin^2(step / 4).
      const double bulge =
          path.circle ? 2.0 * path.radius * std::pow(std::sin(0.25 * step), 2) : 0.0;
      Point prev = path.at(lo);
      for (int k = 1; k <= static_cast<int>(chunks); ++k) {
        const Point next = path.at(k == static_cast<int>(chunks) ? hi : lo + k * step);
        Box chunk;
        chunk.add(prev);
        chunk.add(next);
        chunk = chunk.grown(bulge + reach[a]);
        const int i0 =
            cell_index((chunk.xmin - box_.xmin) / cell_, nx_);
        const int i1 =
            cell_index((chunk.xmax - box_.xmin) / cell_, nx_);
        const int j0 =
            cell_index((chunk.ymin - box_.ymin) / cell_, ny_);
        const int j1 =
            cell_index((chunk.ymax - box_.ymin) / cell_, ny_);
        for (int i = i0; i <= i1; ++i)
          for (int j = j0; j <= j1; ++j) entries.emplace_back(i * ny_ + j, a);
        prev = next;
      }
    }
  }
  std::sort(entries.begin(), entries.end());
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  for (const auto& e : entries) ++cell_start_[e.first + 1];
  for (std::size_t k = 1; k < cell_start_.size(); ++k) cell_start_[k] += cell_start_[k - 1];
  arcs_.reserve(entries.size());
  for (const auto& e : entries) arcs_.push_back(e.second);
}

std::vector<int> ArcLocator::candidates(Point p) const {
  if (!box_.contains(p)) return {};
  const int i = cell_index((p.x - box_.xmin) / cell_, nx_);
  const int j = cell_index((p.y - box_.ymin) / cell_, ny_);
  const int k = i * ny_ + j;
  return {arcs_.begin() + cell_start_[k], arcs_.begin() + cell_start_[k + 1]};
}

}  // namespace covmap::check::detail
