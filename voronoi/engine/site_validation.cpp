#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "voronoi/engine.h"

namespace covmap::voronoi {
namespace {

std::string describe(const std::vector<InvalidSite>& problems) {
  std::ostringstream out;
  out << problems.size() << " invalid site" << (problems.size() == 1 ? "" : "s");
  const std::size_t shown = std::min<std::size_t>(problems.size(), 20);
  for (std::size_t k = 0; k < shown; ++k) {
    const InvalidSite& p = problems[k];
    out << (k == 0 ? ": " : "; ") << "site " << p.index << " ('" << p.id << "'): " << p.problem;
  }
  if (shown < problems.size()) out << "; … and " << problems.size() - shown << " more";
  return out.str();
}

}  // namespace

InvalidSites::InvalidSites(std::vector<InvalidSite> problems)
    : std::runtime_error(describe(problems)), problems_(std::move(problems)) {}

std::vector<InvalidSite> find_invalid_sites(std::span<const Site> sites) {
  std::vector<InvalidSite> problems;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const Site& s = sites[i];
    const int idx = static_cast<int>(i);
    if (!std::isfinite(s.x) || !std::isfinite(s.y))
      problems.push_back({idx, s.id, "coordinates are not finite"});
    if (!std::isfinite(s.weight) || !(s.weight > 0.0)) {
      std::ostringstream m;
      m << "weight must be finite and positive (got " << s.weight << ")";
      problems.push_back({idx, s.id, m.str()});
    }
  }
  // Duplicate positions: sort indices by position, compare neighbours.
  // Only finite positions take part (NaN would break the ordering).
  std::vector<int> order;
  for (std::size_t i = 0; i < sites.size(); ++i)
    if (std::isfinite(sites[i].x) && std::isfinite(sites[i].y)) order.push_back(static_cast<int>(i));
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::pair(sites[a].x, sites[a].y) < std::pair(sites[b].x, sites[b].y);
  });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Site& a = sites[order[k - 1]];
    const Site& b = sites[order[k]];
    if (a.x == b.x && a.y == b.y) {
      std::ostringstream m;
      m << "same position (" << b.x << ", " << b.y << ") as site " << order[k - 1] << " ('" << a.id
        << "')";
      problems.push_back({order[k], b.id, m.str()});
    }
  }
  std::sort(problems.begin(), problems.end(),
            [](const InvalidSite& a, const InvalidSite& b) { return a.index < b.index; });
  return problems;
}

}  // namespace covmap::voronoi
