// Pass 2: every node is weighted-equidistant from the sites of its arcs, and no site is closer.
#include <algorithm>
#include <cmath>

#include "check/check_internal.h"

namespace covmap::check::detail {

void check_nodes(CheckContext& c) {
  const Diagram& d = c.d;
  for (int n = 0; n < static_cast<int>(d.nodes.size()); ++n) {
    const std::vector<int>& own = c.node_sites[n];
    if (!c.node_ok[n] || own.empty()) continue;
    ++c.report.nodes_checked;
    const Point p{d.nodes[n].x, d.nodes[n].y};
    Violation ids;
    ids.node = n;

    // The node's own closest site is the reference; every other own site must be on its bisector.
    // Chosen by bisector_offset rather than raw distances, which lose all digits far out.
    const double tol = c.tol(CheckContext::magnitude(p));
    int best = own.front();
    for (const int s : own)
      if (bisector_offset(p, d.sites[s], d.sites[best]) < 0.0) best = s;
    double worst = 0.0;
    int worst_site = best;
    for (const int s : own) {
      const double off = bisector_offset(p, d.sites[s], d.sites[best]);  // >= 0 up to rounding
      if (off > worst) {
        worst = off;
        worst_site = s;
      }
    }
    if (worst > tol) {
      ids.site = worst_site;
      c.add(ViolationKind::NodeNotEquidistant, p,
            strf("node %d is %.3g off the bisector of its sites %d and %d (tolerance %.3g)", n,
                 worst, best, worst_site, tol),
            ids);
    }

    // Any site strictly closer than the node's closest own site, by more than eps as a length.
    const double bound = CheckContext::closer_bound(weighted_distance(p, d.sites[best]));
    c.owners.for_each_closer(p, bound, [&](int k, double) {
      if (std::find(own.begin(), own.end(), k) != own.end()) return true;
      const double off = bisector_offset(p, d.sites[k], d.sites[best]);
      if (off >= -tol) return true;
      ids.site = k;
      c.add(ViolationKind::NodeSiteCloser, p,
            strf("site %d is closer to node %d than its own site %d (by %.3g as a length)", k, n,
                 best, -off),
            ids);
      return false;
    });
  }
}

}  // namespace covmap::check::detail
