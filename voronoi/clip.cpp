#include "voronoi/clip.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/box.h"
#include "core/point_in_polygon.h"
#include "voronoi/arc_path.h"
#include "voronoi/faces.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi {
namespace {

// A point where an arc meets the boundary: its position along the boundary (edge + t), and the
// sites on either side of the boundary just after it (counter-clockwise).
struct BoundaryMark {
  int edge = 0;
  double t = 0.0;
  int node = kNone;
  int owner_after = kNone;
};

// The clip polygon's boundary as the arcs are cut: the distance under which boundary points are one
// (tolerance::kClipSnap of the polygon's diameter) and the marks where arcs meet it.
struct Boundary {
  const std::vector<Point>& polygon;
  double snap = 0.0;
  std::vector<BoundaryMark> marks;

  // A boundary point as a node of `out`, shared by every arc meeting the boundary there; points
  // within `snap` of a polygon vertex are moved onto it.
  int node_at(int edge, double t, Diagram& out) const {
    const std::size_t m = polygon.size();
    const Point a = polygon[edge], b = polygon[(edge + 1) % m];
    Point p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    if (t * len < snap) p = a, t = 0;
    if ((1 - t) * len < snap) p = b, t = 1;
    for (const BoundaryMark& mk : marks) {
      const Node& q = out.nodes[mk.node];
      if (std::hypot(q.x - p.x, q.y - p.y) <= snap) return mk.node;
    }
    out.nodes.push_back({p.x, p.y});
    return static_cast<int>(out.nodes.size()) - 1;
  }
};

// The diagonal of the polygon's bounding box stands for its diameter (it is between the diameter
// and √2 times it): O(m) where the pairwise diameter takes O(m²), seconds on large polygons.
double snap_distance(const std::vector<Point>& polygon) {
  Box box;
  for (const Point& p : polygon) box.add(p.x, p.y);
  return tolerance::kClipSnap * box.diagonal();
}

// The nodes of d inside the polygon, copied into `out`; per node of d, its index in `out` (kNone
// outside).
std::vector<int> copy_inside_nodes(const Diagram& d, const std::vector<Point>& polygon, Diagram& out) {
  std::vector<int> node_map(d.nodes.size(), kNone);
  for (std::size_t k = 0; k < d.nodes.size(); ++k)
    if (inside_ring(polygon, {d.nodes[k].x, d.nodes[k].y})) {
      node_map[k] = static_cast<int>(out.nodes.size());
      out.nodes.push_back(d.nodes[k]);
    }
  return node_map;
}

// A crossing of an arc with the boundary: its parameter along the arc, and where on the boundary
// (edge + t).
struct Cut {
  double s;
  int edge;
  double t;
};

// Every crossing of the path with the polygon's edges, in the order of the path's parameter.
std::vector<Cut> boundary_cuts(const ArcPathView& path, const std::vector<Point>& polygon) {
  const std::size_t m = polygon.size();
  std::vector<Cut> cuts;
  for (std::size_t e = 0; e < m; ++e) {
    const Point a = polygon[e], b = polygon[(e + 1) % m];
    for (double s : path_segment_crossings(path, a, b)) {
      const Point p = path.at(s);
      const double dx = b.x - a.x, dy = b.y - a.y;
      const double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
      cuts.push_back({s, static_cast<int>(e), std::clamp(t, 0.0, 1.0)});
    }
  }
  std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.s < y.s; });
  return cuts;
}

// An arc no boundary crosses: wholly inside (kept, its ends renumbered) or wholly outside (dropped).
void keep_if_inside(const Arc& arc, const ArcPathView& path, const std::vector<Point>& polygon,
                    const std::vector<int>& node_map, Diagram& out) {
  const double mid = std::isfinite(path.s0) && std::isfinite(path.s1) ? 0.5 * (path.s0 + path.s1)
                     : std::isfinite(path.s0) ? path.s0 + 1 : std::isfinite(path.s1) ? path.s1 - 1 : 0;
  if (!inside_ring(polygon, path.at(mid))) return;
  Arc a = arc;
  a.from = arc.from == kNone ? kNone : node_map[arc.from];
  a.to = arc.to == kNone ? kNone : node_map[arc.to];
  out.arcs.push_back(a);
}

// The node where the arc crosses the boundary at `c`, marked with the site just after it along the
// boundary (counter-clockwise).
int cut_node(const Arc& arc, const ArcPathView& path, const Cut& c, Boundary& boundary, Diagram& out) {
  const std::vector<Point>& polygon = boundary.polygon;
  const int node = boundary.node_at(c.edge, c.t, out);
  const Point tangent = path.tangent(c.s);
  const Point a = polygon[c.edge], b = polygon[(c.edge + 1) % polygon.size()];
  const double cross = tangent.x * (b.y - a.y) - tangent.y * (b.x - a.x);
  boundary.marks.push_back({c.edge, c.t, node, cross > 0 ? arc.left_site : arc.right_site});
  return node;
}

// An arc the boundary crosses: the pieces between consecutive cut parameters (and the arc's ends;
// a closed circle wraps) that lie inside, each as an arc between its two nodes.
void keep_inside_pieces(const Arc& arc, const ArcPathView& path, const std::vector<Cut>& cuts,
                        const std::vector<int>& node_map, Boundary& boundary, Diagram& out) {
  std::vector<double> params;
  std::vector<int> ends;  // node at each param
  if (path.circle && arc.from == arc.to) {
    for (const Cut& c : cuts) params.push_back(c.s), ends.push_back(cut_node(arc, path, c, boundary, out));
    params.push_back(cuts.front().s + (path.s1 - path.s0));
    ends.push_back(ends.front());
  } else {
    params.push_back(path.s0);
    ends.push_back(arc.from == kNone ? kNone : node_map[arc.from]);
    for (const Cut& c : cuts) params.push_back(c.s), ends.push_back(cut_node(arc, path, c, boundary, out));
    params.push_back(path.s1);
    ends.push_back(arc.to == kNone ? kNone : node_map[arc.to]);
  }
  for (std::size_t k = 0; k + 1 < params.size(); ++k) {
    const double s0 = params[k], s1 = params[k + 1];
    const double mid = std::isfinite(s0) && std::isfinite(s1) ? 0.5 * (s0 + s1)
                       : std::isfinite(s0)                    ? s0 + 1
                                                              : s1 - 1;
    if (s1 - s0 <= 0 || !inside_ring(boundary.polygon, path.at(mid))) continue;
    if (ends[k] == kNone || ends[k + 1] == kNone) continue;  // cannot happen inside a polygon
    Arc a = arc;
    a.from = ends[k];
    a.to = ends[k + 1];
    out.arcs.push_back(a);
  }
}

// The site owning the boundary before its first mark (marks sorted along the boundary): the one
// after the last mark, or, when no arc reaches the boundary, the site nearest (by weighted
// distance) to the polygon's first vertex, which owns all of it.
int owner_at_start(const std::vector<BoundaryMark>& marks, const std::vector<Site>& sites,
                   const std::vector<Point>& polygon) {
  if (!marks.empty()) return marks.back().owner_after;
  int owner = kNone;
  double best = 1e300;
  for (std::size_t s = 0; s < sites.size(); ++s) {
    const double v = std::hypot(polygon[0].x - sites[s].x, polygon[0].y - sites[s].y) / sites[s].weight;
    if (v < best) best = v, owner = static_cast<int>(s);
  }
  return owner;
}

// Frame arcs: the boundary split at the marks and at its own vertices, each with the site that
// owns it on its left.
void add_frame_arcs(const std::vector<Site>& sites, Boundary& boundary, Diagram& out) {
  std::vector<BoundaryMark>& marks = boundary.marks;
  const std::vector<Point>& polygon = boundary.polygon;
  const std::size_t m = polygon.size();
  std::sort(marks.begin(), marks.end(), [](const BoundaryMark& a, const BoundaryMark& b) {
    return a.edge != b.edge ? a.edge < b.edge : a.t < b.t;
  });
  int owner = owner_at_start(marks, sites, polygon);
  std::vector<int> vertex_node(m, kNone);
  auto corner = [&](std::size_t v) {
    if (vertex_node[v] == kNone) vertex_node[v] = boundary.node_at(static_cast<int>(v), 0.0, out);
    return vertex_node[v];
  };
  std::size_t mi = 0;
  int current = corner(0);
  for (std::size_t e = 0; e < m; ++e) {
    const Point a = polygon[e], b = polygon[(e + 1) % m];
    auto emit = [&](int to) {
      if (to == current) return;
      Arc f;
      f.frame = true;
      f.curve = Line{a.x, a.y, b.x - a.x, b.y - a.y};
      f.from = current;
      f.to = to;
      f.left_site = owner;
      f.right_site = kNone;
      out.arcs.push_back(f);
      current = to;
    };
    for (; mi < marks.size() && marks[mi].edge == static_cast<int>(e); ++mi) {
      emit(marks[mi].node);
      owner = marks[mi].owner_after;
    }
    emit(corner((e + 1) % m));
  }
}

}  // namespace

Diagram clip_diagram(const Diagram& d, const std::vector<Point>& polygon) {
  if (polygon.size() < 3) throw std::invalid_argument("clip polygon needs at least 3 vertices");
  const double work = static_cast<double>(d.arcs.size() + d.nodes.size()) * static_cast<double>(polygon.size());
  if (work > tolerance::kMaxClipWork)
    throw ClipTooLarge("clipping " + std::to_string(d.arcs.size()) + " arcs to a polygon of " +
                       std::to_string(polygon.size()) + " vertices would take hours (the work grows with their " +
                       "product); simplify the clip polygon");
  Diagram out;
  out.sites = d.sites;
  out.clip = polygon;
  Boundary boundary{polygon, snap_distance(polygon), {}};
  const std::vector<int> node_map = copy_inside_nodes(d, polygon, out);
  for (const Arc& arc : d.arcs) {
    if (arc.frame) continue;
    const ArcPathView path = arc_path(arc, d.nodes);
    const std::vector<Cut> cuts = boundary_cuts(path, polygon);
    if (cuts.empty())
      keep_if_inside(arc, path, polygon, node_map, out);
    else
      keep_inside_pieces(arc, path, cuts, node_map, boundary, out);
  }
  add_frame_arcs(d.sites, boundary, out);
  trace_faces(out);
  return out;
}

}  // namespace covmap::voronoi
