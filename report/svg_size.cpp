// The picture's automatic width (svg.h, svg_layout.h): from the median nearest-neighbour spacing.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "report/svg_layout.h"

namespace covmap::report::detail {
namespace {

// The distance from sites[i] to its nearest other site at a positive distance (infinity if none).
// `order` lists the sites sorted by the coordinate `along` (x or y); the scan walks out from i both
// ways and stops where the sorted coordinate alone is already farther than the best found.
double nearest_distance(std::span<const Site> sites, const std::vector<std::size_t>& order, std::size_t rank,
                        bool along_x) {
  const auto key = [&](std::size_t k) { return along_x ? sites[order[k]].x : sites[order[k]].y; };
  const Site& s = sites[order[rank]];
  double best = std::numeric_limits<double>::infinity();
  const auto visit = [&](std::size_t k) {
    const double d = std::hypot(sites[order[k]].x - s.x, sites[order[k]].y - s.y);
    if (d > 0) best = std::min(best, d);
  };
  for (std::size_t k = rank + 1; k < order.size() && key(k) - key(rank) < best; ++k) visit(k);
  for (std::size_t k = rank; k-- > 0 && key(rank) - key(k) < best;) visit(k);
  return best;
}

}  // namespace

double median_nearest_spacing(std::span<const Site> sites) {
  if (sites.size() < 2) return 0.0;
  // Sort along the longer side of the sites' box: the scan's window is narrowest there.
  double xmin = sites[0].x, xmax = xmin, ymin = sites[0].y, ymax = ymin;
  for (const Site& s : sites) {
    xmin = std::min(xmin, s.x), xmax = std::max(xmax, s.x);
    ymin = std::min(ymin, s.y), ymax = std::max(ymax, s.y);
  }
  const bool along_x = xmax - xmin >= ymax - ymin;
  std::vector<std::size_t> order(sites.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return along_x ? sites[a].x < sites[b].x : sites[a].y < sites[b].y;
  });
  std::vector<std::size_t> rank(sites.size());
  for (std::size_t k = 0; k < order.size(); ++k) rank[order[k]] = k;

  const std::size_t step = std::max<std::size_t>(1, sites.size() / kSpacingSample);
  std::vector<double> spacing;
  for (std::size_t i = 0; i < sites.size(); i += step) {
    const double d = nearest_distance(sites, order, rank[i], along_x);
    if (std::isfinite(d)) spacing.push_back(d);
  }
  if (spacing.empty()) return 0.0;
  const auto middle = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
  std::nth_element(spacing.begin(), middle, spacing.end());
  return *middle;
}

double automatic_width_px(std::span<const Site> sites, const Box& view) {
  const double spacing = median_nearest_spacing(sites);
  if (!(spacing > 0) || !(view.width() > 0)) return kMinWidthPx;
  return std::clamp(view.width() * kSpacingPx / spacing, kMinWidthPx, kMaxWidthPx);
}

}  // namespace covmap::report::detail
