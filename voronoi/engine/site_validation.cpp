#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include <set>

#include "voronoi/engine.h"
#include "voronoi/engine/limits.h"

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

std::string number(double v) {
  std::ostringstream out;
  out.precision(3);
  out << v;
  return out.str();
}

// The supported range (engine/limits.h), for sites already known finite, positive and distinct.
void find_out_of_range(std::span<const Site> sites, std::vector<InvalidSite>& problems) {
  if (sites.size() < 2) return;
  double wmax = 0, xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
  for (const Site& s : sites) {
    wmax = std::max(wmax, s.weight);
    xmin = std::min(xmin, s.x), xmax = std::max(xmax, s.x);
    ymin = std::min(ymin, s.y), ymax = std::max(ymax, s.y);
  }
  // A quarter, so that sites spanning the whole double range do not overflow it.
  const double quarter_extent = std::hypot(0.25 * xmax - 0.25 * xmin, 0.25 * ymax - 0.25 * ymin);
  const double extent = 4 * quarter_extent;  // for messages (may be inf)
  const double wmin_allowed = std::ldexp(wmax, -limits::kWeightRatioExponent);
  const double offset_allowed = std::ldexp(quarter_extent, limits::kOffsetExponent + 2);
  const double separation = std::ldexp(quarter_extent, 2 - limits::kSeparationExponent);
  if (extent < std::ldexp(1.0, limits::kMinExtentExponent)) {
    for (std::size_t i = 0; i < sites.size(); ++i)
      problems.push_back({static_cast<int>(i), sites[i].id,
                          "the sites' extent (" + number(extent) + ") is below 2^" +
                              std::to_string(limits::kMinExtentExponent) +
                              " ≈ 9.3e-302: the diagram's nodes would be denormal doubles with too few digits; "
                              "scale the coordinates up (docs/ENGINE.md, Supported input)"});
    return;
  }
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const Site& s = sites[i];
    if (s.weight < wmin_allowed)
      problems.push_back({static_cast<int>(i), s.id,
                          "weight " + number(s.weight) + " is below 2^-" + std::to_string(limits::kWeightRatioExponent) +
                              " of the largest weight (" + number(wmax) +
                              "); supported weight ratios are up to 2^40 ≈ 1.1e12 (docs/ENGINE.md, Supported input)"});
    if (std::max(std::fabs(s.x), std::fabs(s.y)) > offset_allowed)
      problems.push_back({static_cast<int>(i), s.id,
                          "position (" + number(s.x) + ", " + number(s.y) + ") is more than 2^" +
                              std::to_string(limits::kOffsetExponent) + " ≈ 6.7e7 times the sites' extent (" +
                              number(extent) +
                              ") from the origin, so nodes could not be placed to the precision the diagram needs; "
                              "translate the sites towards the origin (docs/ENGINE.md, Supported input)"});
  }
  // Pairs closer than `separation`: a sweep in x with the sites of the last `separation` in x
  // kept ordered by y.
  std::vector<int> order(sites.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return sites[a].x < sites[b].x; });
  std::set<std::pair<double, int>> window;
  std::size_t tail = 0;
  for (int i : order) {
    const Site& s = sites[i];
    while (sites[order[tail]].x < s.x - separation) window.erase({sites[order[tail]].y, order[tail]}), ++tail;
    for (auto it = window.lower_bound({s.y - separation, -1}); it != window.end() && it->first <= s.y + separation; ++it)
      if (std::hypot(sites[it->second].x - s.x, it->first - s.y) < separation) {
        problems.push_back({i, s.id,
                            "is closer than 2^-" + std::to_string(limits::kSeparationExponent) +
                                " ≈ 8.7e-19 of the sites' extent to site " + std::to_string(it->second) + " ('" +
                                sites[it->second].id + "'); merge them or spread the sites (docs/ENGINE.md, Supported input)"});
        break;
      }
    window.insert({s.y, i});
  }
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
  if (problems.empty()) find_out_of_range(sites, problems);
  std::sort(problems.begin(), problems.end(),
            [](const InvalidSite& a, const InvalidSite& b) { return a.index < b.index; });
  return problems;
}

}  // namespace covmap::voronoi
