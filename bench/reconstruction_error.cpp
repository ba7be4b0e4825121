#include "bench/reconstruction_error.h"

#include <algorithm>
#include <cmath>

#include "core/box.h"

namespace covmap::bench {

std::pair<double, double> reconstruction_error(const std::vector<Site>& truth, const recognition::Reconstruction& r) {
  if (truth.empty()) return {INFINITY, INFINITY};
  Box box;
  double wmax = 0.0;
  for (const Site& s : truth) box.add(s.x, s.y), wmax = std::max(wmax, s.weight);
  const double side_length = std::max({box.xmax - box.xmin, box.ymax - box.ymin, 1e-300});
  const int side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(truth.size()))));
  std::vector<std::vector<int>> cell(static_cast<std::size_t>(side) * side);
  auto column = [&](double x) { return std::clamp(static_cast<int>((x - box.xmin) / side_length * side), 0, side - 1); };
  auto row = [&](double y) { return std::clamp(static_cast<int>((y - box.ymin) / side_length * side), 0, side - 1); };
  for (std::size_t k = 0; k < truth.size(); ++k)
    cell[static_cast<std::size_t>(row(truth[k].y)) * side + column(truth[k].x)].push_back(static_cast<int>(k));
  double worst_position = 0.0, worst_weight = 0.0;
  for (const auto& s : r.sites) {
    double best = INFINITY;
    int match = -1;
    const int ci = column(s.x), cj = row(s.y);
    for (int ring = 0; ring < side && match < 0; ++ring)  // grow the search until something is found,
      for (int j = cj - ring - 1; j <= cj + ring + 1; ++j)  // then one more ring covers the nearest
        for (int i = ci - ring - 1; i <= ci + ring + 1; ++i) {
          if (i < 0 || j < 0 || i >= side || j >= side) continue;
          for (int k : cell[static_cast<std::size_t>(j) * side + i]) {
            const double d = std::hypot(truth[k].x - s.x, truth[k].y - s.y);
            if (d < best) best = d, match = k;
          }
        }
    if (match < 0) return {INFINITY, INFINITY};
    worst_position = std::max(worst_position, best / side_length);
    const double w = truth[match].weight / wmax;
    worst_weight = std::max(worst_weight, std::abs(s.weight - w) / w);
  }
  return {worst_position, worst_weight};
}

}  // namespace covmap::bench
