#include "voronoi/engine/writable_bisectors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <utility>
#include <variant>

#include "voronoi/engine.h"
#include "voronoi/engine/limits.h"

namespace covmap::voronoi::engine {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// How wide the bisector of arc a is, in units of the last place of its coordinates; the limit
// applies to circles (radius) and to lines (distance between the sites: equal weights).
double width_in_ulps(const Diagram& d, const Arc& a) {
  if (const auto* c = std::get_if<Circle>(&a.curve))
    return c->r / (kEps * std::max({std::fabs(c->cx), std::fabs(c->cy), c->r}));
  const Site& p = d.sites[a.left_site];
  const Site& q = d.sites[a.right_site];
  const double magnitude = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(q.x), std::fabs(q.y)});
  return std::hypot(p.x - q.x, p.y - q.y) / (kEps * magnitude);
}

}  // namespace

void refuse_unwritable_bisectors(const Diagram& d) {
  std::set<std::pair<int, int>> pairs;
  for (const Arc& a : d.arcs) {
    if (a.frame || a.left_site == kNone || a.right_site == kNone) continue;
    if (width_in_ulps(d, a) >= limits::kBisectorUlps) continue;
    pairs.insert(std::minmax(a.left_site, a.right_site));
  }
  if (pairs.empty()) return;
  std::vector<InvalidSite> problems;
  for (const auto& [i, j] : pairs)
    for (const auto& [me, other] : {std::pair(i, j), std::pair(j, i)}) {
      std::ostringstream m;
      m << "its bisector with site " << other << " ('" << d.sites[other].id
        << "') would be narrower than " << limits::kBisectorUlps
        << " units in the last place of its coordinates, too narrow to be written in doubles with its sides "
           "told apart; move the two sites apart or merge them (docs/ENGINE.md, Supported input)";
      problems.push_back({me, d.sites[me].id, m.str()});
    }
  std::sort(problems.begin(), problems.end(), [](const InvalidSite& a, const InvalidSite& b) { return a.index < b.index; });
  throw InvalidSites(std::move(problems));
}

}  // namespace covmap::voronoi::engine
