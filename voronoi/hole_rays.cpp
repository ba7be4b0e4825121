// Hole rays for trace_faces() by geometry. Tracing by geometry, every hole would be tested against
// every outer cycle around it. Instead each hole shoots a ray to +x from its rightmost point (there
// its containing face lies just to the right) and takes the first arc hit: the half-arc facing the
// ray's origin bounds the same face, as its outer cycle or as another hole. Holes whose ray meets
// nothing, or meets an arc at a node (ambiguous), fall back to containment tests
// (hole_placement.cpp).
#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "voronoi/arc_path.h"
#include "voronoi/box_grid.h"
#include "voronoi/face_tracing.h"

namespace covmap::voronoi::tracing {
namespace {

// The first arc a ray to +x meets.
struct RayHit {
  double x = INFINITY, ty = 0;  // where, and the y-component of the arc's tangent there
  double uncertainty = 0;       // of x (Crossing::uncertainty)
  int arc = -1;
  bool ambiguous = false;       // another hit as close (through a node)
  bool ambiguous_origin = false;  // an arc other than the hole's passes through the ray's origin
};

// The arcs as rays meet them: all of them (a few holes in a small graph), or through a grid.
class ArcRays {
 public:
  ArcRays(const Diagram& d, const TracingGeometry& geometry, std::size_t holes)
      : d_(d), geometry_(geometry), scan_all_(holes * d.arcs.size() <= (std::size_t{1} << 22)) {
    for (std::size_t a = 0; a < d.arcs.size(); ++a)
      if (unbounded_line(a)) unbounded_arcs_.push_back(static_cast<int>(a));
    nodes_box_ = central_box(d.nodes);
    // About four arcs per cell: a ray crosses few cells before its first hit, and a coarser grid
    // is cheaper to fill.
    // Far arcs of huge circles land in the border cells, which only rays that go that far reach;
    // an arc whose box spans more than four rows' worth of cells (around the whole graph) is
    // tested by every ray instead of filling the grid.
    if (!scan_all_) {
      const std::size_t cells = d.arcs.size() / 4;
      arc_grid_ = make_grid(d.arcs.size(), [&](std::size_t a) { return box_of(a); }, nodes_box_, cells,
                            4 * static_cast<long long>(std::sqrt(static_cast<double>(cells))) + 64);
    }
    stamp_.assign(d.arcs.size(), -1);
  }

  // No finite extent to grid: every hole goes to containment tests.
  bool usable() const { return scan_all_ || arc_grid_.nx != 0; }
  bool has_unbounded_arcs() const { return !unbounded_arcs_.empty(); }

  // The first hit of the ray from `right` (the rightmost point of hole k, whose half-arcs are
  // `hole`).
  RayHit first_hit(Point right, std::size_t k, std::span<const int> hole) {
    RayHit hit;
    hole_ = hole;
    if (scan_all_)
      for (int a : unbounded_arcs_) test_arc(a, right, hit);
    else
      for (int a : arc_grid_.always) test_arc(a, right, hit);
    if (scan_all_) {
      for (std::size_t a = 0; a < d_.arcs.size(); ++a)
        if (!unbounded_line(a)) test_arc(static_cast<int>(a), right, hit);
    } else if (arc_grid_.nx > 0) {
      const int j = arc_grid_.row(right.y);
      for (int i = arc_grid_.column(right.x); i < arc_grid_.nx; ++i) {
        if (i > 0 && hit.x < arc_grid_.x0 + i * arc_grid_.cw) break;  // the nearest hit is left of this cell
        for (int a : arc_grid_.cell(i, j)) {
          if (stamp_[a] == static_cast<int>(k)) continue;  // an arc spans several cells
          stamp_[a] = static_cast<int>(k);
          test_arc(a, right, hit);
        }
      }
    }
    return hit;
  }

 private:
  Box box_of(std::size_t a) const { return to_double(geometry_.box[a]); }
  bool unbounded_line(std::size_t a) const {
    return std::holds_alternative<Line>(d_.arcs[a].curve) && (d_.arcs[a].from == kNone || d_.arcs[a].to == kNone);
  }

  // Where the ray meets an arc: x, the y-component of the arc's tangent there, and how far x may
  // be off — kRayTie of the size of the numbers x is computed from (its own, the ray's height, the
  // circle's radius or the line's anchor). Local, not the nodes' extent: nearly collinear sites put
  // nodes 1e10 out, and a tie window of 1e-12 of that skipped an arc 0.03 from a hole of an
  // extent of 1, placing the hole in the wrong face.
  struct Crossing {
    double x, ty, uncertainty;
    bool at_end = false;  // at one of the arc's end nodes, or along the ray: the ray cannot tell
  };

  // Whether (x, y) lies within `u` of an end node of arc a: the ray passes through a node, where
  // the arcs that end there are all "hit" or (by the strict parameter test) none of them.
  bool near_end(int a, double x, double y, double u) const {
    for (const int v : {d_.arcs[a].from, d_.arcs[a].to}) {
      if (v == kNone) continue;
      const Node& n = d_.nodes[v];
      if (std::abs(n.x - x) <= u + tolerance::kRayTie * std::abs(n.x) && std::abs(n.y - y) <= u + tolerance::kRayTie * std::abs(n.y))
        return true;
    }
    return false;
  }

  // Crossings of the horizontal line y with arc a (box b).
  void crossings(int a, const Box& b, double y) {
    xs_.clear();
    if (!(b.ymin <= y && y <= b.ymax)) return;
    const ArcPathView p = arc_path(d_.arcs[a], d_.nodes);
    if (p.circle) {
      const double dy = y - p.cy;
      const double h2 = p.r * p.r - dy * dy;
      if (h2 <= 0) return;
      const double h = std::sqrt(h2);
      for (double x : {p.cx - h, p.cx + h}) {
        const double s = p.param_of({x, y});
        // A full circle has no end where the ray could pass through a node: its start angle
        // is an ordinary point (concentric circles are hit exactly there).
        const bool full = d_.arcs[a].from == kNone;
        const double u = tolerance::kRayTie * (std::abs(x) + std::abs(y) + p.r);
        const bool end = !full && near_end(a, x, y, u);
        if ((s > p.s0 && s < p.s1) || full || end) xs_.push_back({x, p.tangent(s).y, u, end});
      }
    } else if (p.uy != 0) {
      const double s = (y - p.oy) / p.uy;
      const double x = p.ox + s * p.ux;
      const double u = tolerance::kRayTie * (std::abs(x) + std::abs(y) + std::abs(p.ox) + std::abs(p.oy));
      const bool end = near_end(a, x, y, u);
      if ((s > p.s0 && s < p.s1) || end) xs_.push_back({x, p.uy, u, end});
    } else if (std::abs(y - p.oy) <= tolerance::kRayTie * (std::abs(y) + std::abs(p.oy))) {
      // A horizontal segment along the ray: its nearer end is where the ray meets it, ambiguously.
      const double x0 = p.ox + p.s0 * p.ux, x1 = p.ox + p.s1 * p.ux;
      const double x = std::min(std::isfinite(x0) ? x0 : -INFINITY, std::isfinite(x1) ? x1 : -INFINITY);
      if (std::isfinite(x)) xs_.push_back({x, 0.0, tolerance::kRayTie * (std::abs(x) + std::abs(y)), true});
    }
  }

  void test_arc(int a, Point right, RayHit& hit) {
    const Box b = box_of(static_cast<std::size_t>(a));
    if (b.xmax <= right.x) return;  // wholly left of the ray's origin
    crossings(a, b, right.y);
    const double origin_uncertainty = tolerance::kRayTie * (std::abs(right.x) + std::abs(right.y));
    const bool own = std::any_of(hole_.begin(), hole_.end(), [a](int h) { return h / 2 == a; });
    for (const Crossing& c : xs_) {
      if (c.x <= right.x + origin_uncertainty + c.uncertainty) {
        // Another arc through the ray's origin (a hole tangent to a line there): which side the
        // hole is on is not the ray's to say.
        if (!own && c.x >= right.x - origin_uncertainty - c.uncertainty) hit.ambiguous_origin = true;
        continue;
      }
      if (std::abs(c.x - hit.x) <= c.uncertainty + hit.uncertainty) hit.ambiguous = true;
      if (c.x < hit.x) hit = {c.x, c.ty, c.uncertainty, a, c.at_end};
    }
  }

  const Diagram& d_;
  const TracingGeometry& geometry_;
  // A few holes in a small graph (the usual case: the outer boundary of a weighted diagram)
  // are cheaper to test against every arc than to grid all arcs for.
  bool scan_all_;
  std::vector<int> unbounded_arcs_;
  Box nodes_box_;
  BoxGrid arc_grid_;
  std::vector<Crossing> xs_;
  std::span<const int> hole_;
  LargeVector<int> stamp_;
};

// Rightmost point of a hole (x = -∞ when none is finite).
Point rightmost_point(const Diagram& d, std::span<const int> hole) {
  Point right{-INFINITY, 0};
  for (int hh : hole) {
    const ArcPathView p = arc_path(d.arcs[hh / 2], d.nodes);
    auto consider = [&](Point q) {
      if (q.x > right.x) right = q;
    };
    if (std::isfinite(p.s0)) consider(p.at(p.s0));
    if (std::isfinite(p.s1)) consider(p.at(p.s1));
    if (p.circle) {
      const double t = p.param_of({p.cx + p.r, p.cy});
      if (t >= p.s0 && t <= p.s1) consider(p.at(t));
    }
  }
  return right;
}

}  // namespace

std::vector<int> hole_ray_faces(const Diagram& d, bool by_sites, const TracingGeometry& geometry, const CycleSet& cs,
                                const LargeVector<int>& cycle_of_half, const FaceAssembly& fa) {
  const std::vector<int>& holes = fa.holes;
  std::vector<int> ray_face(holes.size(), -2);  // face, -1 unbounded, -2 undecided
  if (by_sites || holes.empty()) return ray_face;
  ArcRays rays(d, geometry, holes.size());
  for (std::size_t k = 0; k < holes.size(); ++k) {
    const Point right = rightmost_point(d, cs.halves_of(cs.cycles[holes[k]]));
    if (!std::isfinite(right.x)) continue;
    if (!rays.usable()) continue;  // no finite extent to grid: containment tests
    const RayHit hit = rays.first_hit(right, k, cs.halves_of(cs.cycles[holes[k]]));
    if (hit.ambiguous_origin) continue;  // containment tests
    if (hit.arc < 0) {
      ray_face[k] = rays.has_unbounded_arcs() ? -2 : -1;
      continue;
    }
    // Through a node, or tangent to the hit arc: fall back to containment tests.
    if (hit.ambiguous || std::abs(hit.ty) < tolerance::kRayTangent) continue;
    // The half-arc facing -x (the ray's origin) on its left: tangent pointing up.
    const int hit_cycle = cycle_of_half[half_id(hit.arc, hit.ty > 0)];
    if (hit_cycle < 0) continue;
    if (fa.face_of_cycle[hit_cycle] >= 0) ray_face[k] = fa.face_of_cycle[hit_cycle];
    else if (fa.hole_of_cycle[hit_cycle] != static_cast<int>(k)) ray_face[k] = -3 - fa.hole_of_cycle[hit_cycle];
  }
  // Resolve chains of holes (-3 - other) to faces.
  for (std::size_t k = 0; k < holes.size(); ++k) {
    int v = ray_face[k], steps = 0;
    while (v <= -3 && steps++ <= static_cast<int>(holes.size())) v = ray_face[-3 - v];
    ray_face[k] = v <= -3 ? -2 : v;
  }
  return ray_face;
}

}  // namespace covmap::voronoi::tracing
