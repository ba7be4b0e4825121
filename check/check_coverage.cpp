// Pass 4: every boundary of the true diagram that random probes find has an arc on it.
//
// A probe is a random segment whose ends have different brute-force owners. Bisecting it (keeping
// ends with different owners) converges on a point where two regions of the true diagram meet;
// the diagram must have an arc of exactly those two sites there, or a node of both when the point
// landed next to a node (where the owners at the two ends need not be neighbours along an arc).
#include <algorithm>
#include <cmath>
#include <random>

#include "check/arc_locator.h"
#include "check/check_internal.h"

namespace covmap::check::detail {
namespace {

bool has(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

bool is_covered(const CheckContext& c, const ArcLocator& locator, Point x, int sa, int sb,
                const std::vector<double>& arc_reach) {
  for (const int a : locator.candidates(x)) {
    const double reach = arc_reach[a];
    const Arc& arc = c.d.arcs[a];
    const ArcPath& path = *c.paths[a];
    const bool pair = (arc.left_site == sa && arc.right_site == sb) ||
                      (arc.left_site == sb && arc.right_site == sa);
    if (pair && distance_to_arc(path, x) <= reach) return true;
    for (const int n : {arc.from, arc.to}) {
      if (n == kNone) continue;
      const Point p{c.d.nodes[n].x, c.d.nodes[n].y};
      if (std::hypot(p.x - x.x, p.y - x.y) <= reach && has(c.node_sites[n], sa) &&
          has(c.node_sites[n], sb))
        return true;
    }
  }
  return false;
}

}  // namespace

void check_coverage(CheckContext& c) {
  const CheckOptions& o = c.options;
  const long valid_sites = std::count(c.site_ok.begin(), c.site_ok.end(), 1);
  if (o.boundary_probes == 0 || valid_sites < 2) return;

  Box probe_box;
  if (!c.d.clip.empty()) {
    for (const Point& p : c.d.clip) probe_box.add(p);
  } else {
    for (std::size_t i = 0; i < c.d.sites.size(); ++i)
      if (c.site_ok[i]) probe_box.add({c.d.sites[i].x, c.d.sites[i].y});
    probe_box = probe_box.grown(o.probe_margin * c.scale);
  }
  const double stop_length = o.bisection_tolerance * c.scale;
  const double reach = o.coverage_factor * c.eps + stop_length;

  // Only bisector arcs separate regions; frame arcs are left out of the locator. Each arc's reach
  // adds the rounding of the numbers that state it: a circle of radius 5e12 (weights equal to 12
  // digits) is only known to ~1e-3, so a boundary point on it can be that far from its curve.
  std::vector<std::optional<ArcPath>> bisectors = c.paths;
  std::vector<double> arc_reach(bisectors.size(), reach);
  for (std::size_t a = 0; a < bisectors.size(); ++a) {
    if (c.d.arcs[a].frame) bisectors[a].reset();
    if (bisectors[a]) arc_reach[a] = reach + c.rounding(representation_magnitude(*bisectors[a]));
  }
  const ArcLocator locator(bisectors, probe_box, arc_reach);

  // mt19937_64 is specified bit for bit; the conversion to [0, 1) below is too, so a seed gives
  // the same probes on every platform (std::uniform_real_distribution would not).
  std::mt19937_64 rng(o.seed);
  const auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const auto random_point = [&] {
    return Point{probe_box.xmin + uniform() * (probe_box.xmax - probe_box.xmin),
                 probe_box.ymin + uniform() * (probe_box.ymax - probe_box.ymin)};
  };

  const long max_attempts = 50L * o.boundary_probes + 100;
  for (long attempt = 0; attempt < max_attempts && c.report.boundary_points_checked <
                                                       static_cast<std::size_t>(o.boundary_probes);
       ++attempt) {
    Point a = random_point(), b = random_point();
    if (!c.in_clip(a) || !c.in_clip(b)) continue;
    int owner_a = c.owners.nearest(a), owner_b = c.owners.nearest(b);
    if (owner_a == owner_b) continue;
    while (std::hypot(b.x - a.x, b.y - a.y) > stop_length) {
      const Point m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
      if ((m.x == a.x && m.y == a.y) || (m.x == b.x && m.y == b.y)) break;  // out of doubles
      const int owner_m = c.owners.nearest(m);
      if (owner_m == owner_a) {
        a = m;
      } else {
        b = m;
        owner_b = owner_m;
      }
    }
    const Point x{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
    if (!c.in_clip(x)) continue;
    ++c.report.boundary_points_checked;
    if (is_covered(c, locator, x, owner_a, owner_b, arc_reach)) continue;
    Violation ids;
    ids.site = owner_a;
    c.add(ViolationKind::BoundaryNotCovered, x,
          strf("the regions of sites %d and %d meet at (%.17g, %.17g) but no arc of that pair (or "
               "node of both) is within %.3g (plus the rounding of the arc's own numbers)",
               owner_a, owner_b, x.x, x.y, reach),
          ids);
  }
}

}  // namespace covmap::check::detail
