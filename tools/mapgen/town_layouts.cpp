#include "tools/mapgen/town_layouts.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "tools/mapgen/random_stream.h"
#include "core/diagram.h"

namespace covmap::mapgen {
namespace {

// Degrees on a local equirectangular plane about (lon0, lat0): enough to rank nearness within a
// region (not used for any position that is written).
struct LocalDegrees {
  double lon0 = 0.0;
  double cos_lat0 = 1.0;
  double lat0 = 0.0;

  Point operator()(const LonLatSite& s) const {
    double dlon = s.lon - lon0;
    if (dlon > 180.0) dlon -= 360.0;
    if (dlon < -180.0) dlon += 360.0;
    return {dlon * cos_lat0, s.lat - lat0};
  }
};

double squared(Point a, Point b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); }

void check(std::span<const LonLatSite> towns, const TownLayoutOptions& o) {
  if (o.count < 2) throw std::invalid_argument("town layout: the window needs at least 2 towns");
  if (static_cast<std::size_t>(o.count) > towns.size())
    throw std::invalid_argument("town layout: the window of " + std::to_string(o.count) + " towns is larger than the list (" +
                                std::to_string(towns.size()) + " towns)");
  if (!(std::isfinite(o.alpha) && o.alpha > 0.0)) throw std::invalid_argument("town layout: alpha must be positive");
  if (o.weights == TownWeights::kPowerClasses) {
    if (o.power_classes_dbm.empty()) throw std::invalid_argument("town layout: power classes must not be empty");
    for (const double p : o.power_classes_dbm)
      if (!std::isfinite(p)) throw std::invalid_argument("town layout: power classes must be finite");
  }
}

// Weights from tx-power classes by local spacing rank (see the header).
void assign_power_classes(std::vector<LonLatSite>& sites, const LocalDegrees& plane, const TownLayoutOptions& o) {
  std::vector<double> spacing(sites.size(), std::numeric_limits<double>::infinity());
  for (std::size_t a = 0; a < sites.size(); ++a)
    for (std::size_t b = 0; b < sites.size(); ++b)
      if (a != b) spacing[a] = std::min(spacing[a], squared(plane(sites[a]), plane(sites[b])));
  std::vector<std::size_t> rank(sites.size());
  std::iota(rank.begin(), rank.end(), std::size_t{0});
  std::stable_sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t b) { return spacing[a] > spacing[b]; });
  std::vector<double> classes = o.power_classes_dbm;
  std::sort(classes.begin(), classes.end(), std::greater<>());
  const double top = classes.front();
  for (std::size_t r = 0; r < rank.size(); ++r) {
    const std::size_t c = r * classes.size() / rank.size();  // equal groups, most isolated first
    sites[rank[r]].weight = std::pow(10.0, (classes[c] - top) / (10.0 * o.alpha));
  }
}

}  // namespace

std::string_view to_string(TownWeights weights) {
  switch (weights) {
    case TownWeights::kPopulation: return "population";
    case TownWeights::kPowerClasses: return "power-classes";
  }
  return "?";
}

std::optional<TownWeights> town_weights_from_string(std::string_view text) {
  for (const TownWeights w : {TownWeights::kPopulation, TownWeights::kPowerClasses})
    if (to_string(w) == text) return w;
  return std::nullopt;
}

TownWindow clustered_town_sites(std::span<const LonLatSite> towns, const TownLayoutOptions& options) {
  check(towns, options);
  RandomStream random(options.seed, RandomPurpose::kTownLayout);
  TownWindow out;
  out.centre = static_cast<std::size_t>(random.below(towns.size()));
  const LonLatSite& c = towns[out.centre];
  const LocalDegrees plane{c.lon, std::cos(c.lat * std::numbers::pi / 180.0), c.lat};
  const Point origin = plane(c);
  std::vector<std::size_t> order(towns.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<double> distance(towns.size());
  for (std::size_t k = 0; k < towns.size(); ++k) distance[k] = squared(plane(towns[k]), origin);
  const auto nearer = [&](std::size_t a, std::size_t b) { return distance[a] < distance[b] || (distance[a] == distance[b] && a < b); };
  const auto cut = order.begin() + options.count;
  std::partial_sort(order.begin(), cut, order.end(), nearer);
  order.erase(cut, order.end());
  std::sort(order.begin(), order.end());
  for (const std::size_t k : order) out.sites.push_back(towns[k]);
  if (options.weights == TownWeights::kPowerClasses) assign_power_classes(out.sites, plane, options);
  return out;
}

}  // namespace covmap::mapgen
