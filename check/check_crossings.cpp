// Pass 5: no two arcs meet except at their end nodes.
//
// Candidate pairs come from a sort-and-sweep over bounding boxes (unbounded lines clipped to a box
// one scale beyond everything the diagram names), then the two full curves are intersected exactly
// and each intersection point is tested for lying inside both arcs, away from their end nodes.
#include <algorithm>
#include <cmath>

#include "check/check_internal.h"

namespace covmap::check::detail {
namespace {

struct Item {
  Box box;
  int arc;
};

// One point well inside the arc (its middle, or the middle of its sampled stretch).
Point middle_of(const CheckContext& c, const ArcPath& path) {
  return path.at(sample_parameters(path, 1, c.region, c.scale).front());
}

// How far from the end nodes an intersection must be to count. Curves known to within tol meet
// somewhere in a window tol / sin(angle) long along them, so nearly tangent arcs (far nodes, nearly
// equal weights) get a wide berth, and exactly tangent ones are never reported. An end node off its
// curve (already an ArcEndNotOnCurve) moves the meeting point the same way, so its gap is added:
// otherwise every misplaced node would also be reported as a crossing of its own arcs.
double crossing_margin(const CheckContext& c, const ArcPath& pa, const ArcPath& pb, Point x) {
  const auto size = [](const ArcPath& p) {
    return p.circle ? CheckContext::magnitude(p.centre) + p.radius
                    : CheckContext::magnitude(p.origin);
  };
  const double tol = c.tol(std::max({CheckContext::magnitude(x), size(pa), size(pb)}));
  const Point ta = curve_direction_at(pa, x), tb = curve_direction_at(pb, x);
  const double sine = std::abs(ta.x * tb.y - ta.y * tb.x);
  const double known_to = tol + pa.end_gap + pb.end_gap;
  return sine > 0.0 ? known_to / sine : kInfinity;
}

// Curves known to within their margin that meet only inside one uncertainty window may in truth
// just touch: the regions of an exactly degenerate diagram touch at a point (two disks of a grid
// whose bisector circles are tangent), and a perturbation below the rounding leaves them touching,
// apart or overlapping by less than the numbers can tell. That is a touch, not a crossing: the two
// intersection points lie within one margin of each other, or tangency within eps gave just one,
// whose margin (curves parallel there) exceeds the diagram's scale. Full circles have no end nodes
// to measure the margin from, so without this every such pair was reported.
bool may_only_touch(const CheckContext& c, const CurveIntersection& hit, Point x, double margin) {
  if (hit.points.size() == 1) return margin >= c.scale;
  for (const Point& y : hit.points)
    if ((y.x != x.x || y.y != x.y) && std::hypot(y.x - x.x, y.y - x.y) <= margin) return true;
  return false;
}

void test_pair(CheckContext& c, int a, int b) {
  const ArcPath& pa = *c.paths[a];
  const ArcPath& pb = *c.paths[b];
  ++c.report.crossings_tested;
  Violation ids;
  ids.arc = a;
  ids.other_arc = b;
  const CurveIntersection hit = intersect_curves(pa, pb, c.eps, c.scale);
  if (hit.coincident) {
    // Same curve: they overlap if the middle of either lies inside the other.
    for (const auto& [p, q] : {std::pair{&pa, &pb}, std::pair{&pb, &pa}}) {
      const Point m = middle_of(c, *p);
      if (distance_to_arc(*q, m) <= c.eps && is_interior_point(*q, m, c.eps) &&
          is_interior_point(*p, m, c.eps)) {
        c.add(ViolationKind::ArcsCross, m,
              strf("arcs %d and %d overlap along the same curve", a, b), ids);
        return;
      }
    }
    return;
  }
  for (const Point& x : hit.points) {
    const double margin = crossing_margin(c, pa, pb, x);
    if (may_only_touch(c, hit, x, margin)) continue;
    if (is_interior_point(pa, x, margin) && is_interior_point(pb, x, margin)) {
      c.add(
          ViolationKind::ArcsCross, x,
          strf("arcs %d and %d cross at (%.17g, %.17g), away from their end nodes", a, b, x.x, x.y),
          ids);
      return;
    }
  }
}

}  // namespace

void check_crossings(CheckContext& c) {
  const Box limit = c.region.grown(c.scale);
  std::vector<Item> items;
  for (int a = 0; a < static_cast<int>(c.paths.size()); ++a) {
    if (!c.paths[a]) continue;
    const Box box = bounding_box(*c.paths[a], limit);
    // Grown by eps so arcs that only touch within the tolerance are still compared.
    if (!box.empty()) items.push_back({box.grown(c.eps), a});
  }
  std::sort(items.begin(), items.end(),
            [](const Item& p, const Item& q) { return p.box.xmin < q.box.xmin; });
  for (std::size_t i = 0; i < items.size(); ++i) {
    for (std::size_t j = i + 1; j < items.size() && items[j].box.xmin <= items[i].box.xmax; ++j) {
      if (items[i].box.ymin <= items[j].box.ymax && items[j].box.ymin <= items[i].box.ymax)
        test_pair(c, std::min(items[i].arc, items[j].arc), std::max(items[i].arc, items[j].arc));
    }
  }
}

}  // namespace covmap::check::detail
