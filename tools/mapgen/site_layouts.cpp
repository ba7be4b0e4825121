#include "tools/mapgen/site_layouts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "tools/mapgen/random_stream.h"

namespace covmap::mapgen {

double mean_nearest_neighbour_distance(std::span<const Site> sites) {
  if (sites.size() < 2) throw std::invalid_argument("mean nearest-neighbour distance needs at least two sites");
  std::vector<std::size_t> order(sites.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sites[a].x < sites[b].x; });
  double sum = 0.0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto& s = sites[order[k]];
    double best = std::numeric_limits<double>::infinity();
    // Scan outwards in x order; stop once the x gap alone exceeds the best distance so far.
    for (std::size_t m = k + 1; m < order.size() && sites[order[m]].x - s.x < best; ++m)
      best = std::min(best, std::hypot(sites[order[m]].x - s.x, sites[order[m]].y - s.y));
    for (std::size_t m = k; m-- > 0 && s.x - sites[order[m]].x < best;)
      best = std::min(best, std::hypot(sites[order[m]].x - s.x, sites[order[m]].y - s.y));
    sum += best;
  }
  return sum / static_cast<double>(sites.size());
}

std::vector<Site> random_sites(const RandomSitesOptions& options) {
  if (options.count < 1) throw std::invalid_argument("random sites: count must be at least 1");
  if (!(options.width_m > 0.0) || !(options.height_m > 0.0) || !std::isfinite(options.width_m) ||
      !std::isfinite(options.height_m))
    throw std::invalid_argument("random sites: the area must have positive, finite width and height");
  if (!(options.weight_ratio >= 1.0) || !std::isfinite(options.weight_ratio))
    throw std::invalid_argument("random sites: weight ratio must be a finite number >= 1");
  RandomStream random(options.seed, RandomPurpose::kRandomLayout);
  const double log_ratio = std::log(options.weight_ratio);
  std::vector<Site> sites;
  sites.reserve(static_cast<std::size_t>(options.count));
  for (int k = 0; k < options.count; ++k) {
    char id[16];
    std::snprintf(id, sizeof id, "r%04d", k + 1);
    Site s;
    s.id = id;
    s.x = random.uniform(-0.5, 0.5) * options.width_m;
    s.y = random.uniform(-0.5, 0.5) * options.height_m;
    s.weight = std::exp(-log_ratio * random.uniform());
    sites.push_back(std::move(s));
  }
  return sites;
}

}  // namespace covmap::mapgen
