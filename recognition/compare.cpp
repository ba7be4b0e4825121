#include "recognition/tolerances.h"
#include "recognition/compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "core/extent.h"
#include "voronoi/arc_path.h"
#include "voronoi/box_grid.h"

namespace covmap::recognition {
namespace {


struct Grid {
  double cell;
  std::unordered_map<long long, std::vector<int>> buckets;
  static long long key(long long x, long long y) { return x * 73856093LL ^ y * 19349663LL; }
  long long ix(double v) const { return static_cast<long long>(std::floor(v / cell)); }
  void add(double x, double y, int i) { buckets[key(ix(x), ix(y))].push_back(i); }
  template <class F>
  void near(double x, double y, F&& f) const {
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        auto it = buckets.find(key(ix(x) + dx, ix(y) + dy));
        if (it != buckets.end())
          for (int i : it->second) f(i);
      }
  }
};

Point midpoint(const Diagram& d, const Arc& a) {
  const voronoi::ArcPathView p = voronoi::arc_path(a, d.nodes);
  const double s = std::isfinite(p.s0) && std::isfinite(p.s1) ? 0.5 * (p.s0 + p.s1)
                   : std::isfinite(p.s0)                       ? p.s0 + 1.0
                   : std::isfinite(p.s1)                       ? p.s1 - 1.0
                                                               : 0.0;
  return p.at(s);
}

// Distance from q to an arc (its parameter range only).
double distance_to_arc(const voronoi::ArcPathView& p, Point q) {
  double s;
  if (p.circle) {
    const double angle = std::atan2(q.y - p.cy, q.x - p.cx);
    s = std::fmod(p.sense * (angle - p.start_angle), 6.283185307179586);
    if (s < 0) s += 6.283185307179586;
    if (s > p.s1) {
      const Point e0 = p.at(p.s0), e1 = p.at(p.s1);
      return std::min(std::hypot(q.x - e0.x, q.y - e0.y), std::hypot(q.x - e1.x, q.y - e1.y));
    }
  } else {
    s = std::clamp((q.x - p.ox) * p.ux + (q.y - p.oy) * p.uy, p.s0, p.s1);
  }
  const Point on = p.at(s);
  return std::hypot(q.x - on.x, q.y - on.y);
}

// "Is q within tol of the graph?" for many points: the arcs' paths computed once, and their boxes
// in a uniform grid over the central nodes (boxes reaching beyond it land in the border cells, which
// the clamped query reaches too). Arcs whose box covers many cells (far, huge circles; unbounded
// lines) are kept apart and always tested. Without the grid the check filtered each difference
// against every arc: 26 differences of a 10^5-site diagram took 9 s.
class ArcProximity {
 public:
  explicit ArcProximity(const Diagram& d) {
    paths_.reserve(d.arcs.size());
    for (const Arc& a : d.arcs) paths_.push_back(voronoi::arc_path(a, d.nodes));
    const Box e = robust_extent(d.nodes);
    grid_ = voronoi::make_grid(
        d.arcs.size(), [&](std::size_t k) { return voronoi::arc_bounds(d.arcs[k], d.nodes); },
        e, d.arcs.size(), kMaxCells);
  }

  bool near(Point q, double tol) const {
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(tol)) return false;
    auto close = [&](int k) { return distance_to_arc(paths_[k], q) <= tol; };
    if (std::any_of(grid_.always.begin(), grid_.always.end(), close)) return true;
    if (grid_.nx == 0) return false;  // every arc is in `always`
    const int i0 = grid_.column(q.x - tol), i1 = grid_.column(q.x + tol);
    const int j0 = grid_.row(q.y - tol), j1 = grid_.row(q.y + tol);
    if (static_cast<long long>(i1 - i0 + 1) * (j1 - j0 + 1) > kMaxCells) {  // a huge allowance
      for (std::size_t k = 0; k < paths_.size(); ++k)
        if (close(static_cast<int>(k))) return true;
      return false;
    }
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        for (int k : grid_.cell(i, j))
          if (close(k)) return true;
    return false;
  }

 private:
  // Arcs whose box covers more cells (far, huge circles) are tested for every point instead.
  static constexpr long long kMaxCells = 64;

  std::vector<voronoi::ArcPathView> paths_;
  voronoi::BoxGrid grid_;
};

std::vector<Point> arc_samples(const Diagram& d, const Arc& arc, double far) {
  const voronoi::ArcPathView p = voronoi::arc_path(arc, d.nodes);
  const double s0 = std::isfinite(p.s0) ? p.s0 : (std::isfinite(p.s1) ? p.s1 - far : -far);
  const double s1 = std::isfinite(p.s1) ? p.s1 : s0 + 2 * far;
  std::vector<Point> out;
  for (int k = 1; k < 8; ++k) out.push_back(p.at(s0 + (s1 - s0) * k / 8.0));
  return out;
}

bool same_curve(const Arc& a, const Arc& b, double tol) {
  const auto* ca = std::get_if<Circle>(&a.curve);
  const auto* cb = std::get_if<Circle>(&b.curve);
  if (ca && cb)
    return std::hypot(ca->cx - cb->cx, ca->cy - cb->cy) <= tol && std::abs(ca->r - cb->r) <= tol;
  if (!ca && !cb) {
    const auto& la = std::get<Line>(a.curve);
    const auto& lb = std::get<Line>(b.curve);
    const double na = std::hypot(la.dx, la.dy), nb = std::hypot(lb.dx, lb.dy);
    const double cross = (la.dx * lb.dy - la.dy * lb.dx) / (na * nb);
    const double offset = std::abs((lb.x - la.x) * la.dy - (lb.y - la.y) * la.dx) / na;
    return std::abs(cross) <= tolerance::kSameDirectionSine && offset <= tol;
  }
  return false;  // a circle and a line (a huge circle against a line is a different curve here)
}

}  // namespace

const char* to_string(DifferenceKind kind) {
  switch (kind) {
    case DifferenceKind::NodeOnlyInA: return "NodeOnlyInA";
    case DifferenceKind::NodeOnlyInB: return "NodeOnlyInB";
    case DifferenceKind::ArcOnlyInA: return "ArcOnlyInA";
    case DifferenceKind::ArcOnlyInB: return "ArcOnlyInB";
  }
  return "?";
}

std::string Comparison::brief() const {
  std::ostringstream o;
  if (equal()) {
    o << "equal (" << nodes_matched << " nodes, " << arcs_matched << " arcs matched)";
    return o.str();
  }
  o << differences.size() << " differences (" << nodes_matched << " nodes, " << arcs_matched
    << " arcs matched); first: " << differences.front().message;
  return o.str();
}

Comparison compare_graphs(const Diagram& a, const Diagram& b, const CompareOptions& options) {
  Comparison out;
  // The extent: the central part of the first graph's nodes and full circles (core/extent.h) and both
  // graphs' sites (not the second graph's nodes, which may hold the far artefacts the horizon is
  // there to ignore).
  const Diagram& reference = a.arcs.empty() ? b : a;
  const Box e = graph_extent(reference);
  double xmin = e.xmin, xmax = e.xmax, ymin = e.ymin, ymax = e.ymax;
  if (reference.arcs.empty() && reference.nodes.empty()) xmin = ymin = INFINITY, xmax = ymax = -INFINITY;
  for (const Diagram* d : {&a, &b})
    for (const auto& s : d->sites) {
      xmin = std::min(xmin, s.x), xmax = std::max(xmax, s.x);
      ymin = std::min(ymin, s.y), ymax = std::max(ymax, s.y);
    }
  const double scale =
      std::isfinite(xmax - xmin) ? std::max(std::hypot(xmax - xmin, ymax - ymin), 1e-300) : 1.0;
  const double tol = options.relative_tolerance * scale;
  const Point centre{0.5 * (xmin + xmax), 0.5 * (ymin + ymax)};
  const double horizon = options.horizon * scale;
  auto far_node = [&](const Diagram& d, int v) {
    return v == kNone || std::hypot(d.nodes[v].x - centre.x, d.nodes[v].y - centre.y) > horizon;
  };
  // An arc beyond the horizon: both ends far (or at infinity) and its nearest point to the centre
  // far too.
  auto beyond = [&](const Diagram& d, const Arc& arc) {
    if (!far_node(d, arc.from) || !far_node(d, arc.to)) return false;
    const voronoi::ArcPathView p = voronoi::arc_path(arc, d.nodes);
    double s;
    if (p.circle) {
      const double angle = std::atan2(centre.y - p.cy, centre.x - p.cx);
      s = std::fmod(p.sense * (angle - p.start_angle), 6.283185307179586);
      if (s < 0) s += 6.283185307179586;
      if (s < p.s0 || s > p.s1) return true;  // the nearest point is an end: far
    } else {
      s = std::clamp((centre.x - p.ox) * p.ux + (centre.y - p.oy) * p.uy, p.s0, p.s1);
    }
    const Point q = p.at(s);
    return std::hypot(q.x - centre.x, q.y - centre.y) > horizon;
  };
  // Nodes closer than tol within one graph are one node (a node of degree four may be recomputed
  // as two of degree three joined by an arc shorter than the tolerance): cluster them, and ignore
  // arcs inside a cluster.
  auto clusters = [&](const Diagram& d) {
    std::vector<int> parent(d.nodes.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
    auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for (const Arc& arc : d.arcs)
      if (arc.from != kNone && arc.to != kNone && arc.from != arc.to &&
          std::hypot(d.nodes[arc.from].x - d.nodes[arc.to].x, d.nodes[arc.from].y - d.nodes[arc.to].y) <= tol)
        parent[find(arc.from)] = find(arc.to);
    std::vector<int> root(d.nodes.size());
    for (std::size_t i = 0; i < root.size(); ++i) root[i] = find(static_cast<int>(i));
    return root;
  };
  const std::vector<int> ca = clusters(a), cb = clusters(b);
  // An arc inside one cluster that is itself that short; a long arc between two clustered nodes
  // (a circle nearly touching itself there) is a loop through the cluster and is compared.
  auto tiny = [&](const Diagram& d, const std::vector<int>& c, const Arc& arc) {
    if (arc.from == kNone || arc.to == kNone || arc.from == arc.to || c[arc.from] != c[arc.to])
      return false;
    const voronoi::ArcPathView p = voronoi::arc_path(arc, d.nodes);
    const double length = p.circle ? p.r * (p.s1 - p.s0) : std::abs(p.s1 - p.s0);
    return length <= 2 * tol;
  };

  // Nodes: each cluster of a to the nearest unused cluster of b within tol.
  Grid grid{tol, {}};
  for (std::size_t j = 0; j < b.nodes.size(); ++j)
    if (cb[j] == static_cast<int>(j) && !far_node(b, static_cast<int>(j)))
      grid.add(b.nodes[j].x, b.nodes[j].y, static_cast<int>(j));
  std::vector<int> a_to_b(a.nodes.size(), kNone), b_to_a(b.nodes.size(), kNone);
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    if (ca[i] != static_cast<int>(i) || far_node(a, static_cast<int>(i))) continue;
    int best = kNone;
    double best_d = tol;
    grid.near(a.nodes[i].x, a.nodes[i].y, [&](int j) {
      const double dd = std::hypot(a.nodes[i].x - b.nodes[j].x, a.nodes[i].y - b.nodes[j].y);
      if (b_to_a[j] == kNone && dd <= best_d) best = j, best_d = dd;
    });
    if (best != kNone) {
      a_to_b[i] = best;
      b_to_a[best] = static_cast<int>(i);
      ++out.nodes_matched;
    }
  }
  // Far from the sites, positions of nodes and circles are sensitive to the sites' rounding in
  // proportion to their distance (nearly tangent bisectors): unmatched nodes get a second chance
  // with the tolerance scaled by their distance from the centre, in units of the extent.
  auto scaled_tol = [&](double x, double y) {
    return tol * std::max(1.0, std::hypot(x - centre.x, y - centre.y) / scale);
  };
  {
    std::vector<int> ua, ub;
    for (std::size_t i = 0; i < a.nodes.size(); ++i)
      if (ca[i] == static_cast<int>(i) && a_to_b[i] == kNone && !far_node(a, static_cast<int>(i)))
        ua.push_back(static_cast<int>(i));
    for (std::size_t j = 0; j < b.nodes.size(); ++j)
      if (cb[j] == static_cast<int>(j) && b_to_a[j] == kNone && !far_node(b, static_cast<int>(j)))
        ub.push_back(static_cast<int>(j));
    if (ua.size() * ub.size() <= 4000000)
      for (int i : ua) {
        int best = kNone;
        double best_d = scaled_tol(a.nodes[i].x, a.nodes[i].y);
        for (int j : ub) {
          if (b_to_a[j] != kNone) continue;
          const double dd = std::hypot(a.nodes[i].x - b.nodes[j].x, a.nodes[i].y - b.nodes[j].y);
          if (dd <= best_d) best = j, best_d = dd;
        }
        if (best != kNone) {
          a_to_b[i] = best;
          b_to_a[best] = i;
          ++out.nodes_matched;
        }
      }
  }
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    if (ca[i] == static_cast<int>(i) && a_to_b[i] == kNone && !far_node(a, static_cast<int>(i))) {
      std::ostringstream m;
      m << "node " << i << " at (" << a.nodes[i].x << ", " << a.nodes[i].y << ") only in the first graph";
      out.differences.push_back({DifferenceKind::NodeOnlyInA, static_cast<int>(i), a.nodes[i].x, a.nodes[i].y, m.str()});
    }
  for (std::size_t j = 0; j < b.nodes.size(); ++j)
    if (cb[j] == static_cast<int>(j) && b_to_a[j] == kNone && !far_node(b, static_cast<int>(j))) {
      std::ostringstream m;
      m << "node " << j << " at (" << b.nodes[j].x << ", " << b.nodes[j].y << ") only in the second graph";
      out.differences.push_back({DifferenceKind::NodeOnlyInB, static_cast<int>(j), b.nodes[j].x, b.nodes[j].y, m.str()});
    }

  // Arcs: by their end nodes (in b's numbering, unordered) and curve.
  auto key = [](int u, int v) {
    if (u > v) std::swap(u, v);
    return (static_cast<long long>(u) + 2) * 4000000007LL + (v + 2);
  };
  std::unordered_map<long long, std::vector<int>> b_arcs;
  // A curve's own numbers are known in proportion to their size (see scaled_tol).
  auto curve_tol = [&](const Arc& arc) {
    if (const auto* c = std::get_if<Circle>(&arc.curve))
      return tol * std::max(1.0, (std::hypot(c->cx - centre.x, c->cy - centre.y) + c->r) / scale);
    return tol;
  };
  // Arc ends in b's node numbering: cluster representatives, far nodes as infinity.
  auto b_end = [&](int v) { return far_node(b, v) ? kNone : cb[v]; };
  for (std::size_t j = 0; j < b.arcs.size(); ++j)
    b_arcs[key(b_end(b.arcs[j].from), b_end(b.arcs[j].to))].push_back(static_cast<int>(j));
  std::vector<char> b_used(b.arcs.size(), 0);
  for (std::size_t i = 0; i < a.arcs.size(); ++i) {
    const Arc& arc = a.arcs[i];
    if (tiny(a, ca, arc) || beyond(a, arc)) continue;
    const bool from_inf = far_node(a, arc.from), to_inf = far_node(a, arc.to);
    const int u = from_inf ? kNone : a_to_b[ca[arc.from]];
    const int v = to_inf ? kNone : a_to_b[ca[arc.to]];
    bool matched = false;
    if ((from_inf || u != kNone) && (to_inf || v != kNone)) {
      auto it = b_arcs.find(key(u, v));
      if (it != b_arcs.end())
        for (int j : it->second)
          if (!b_used[j] && same_curve(arc, b.arcs[j], curve_tol(arc))) {
            b_used[j] = 1;
            matched = true;
            ++out.arcs_matched;
            break;
          }
    }
    if (!matched) {
      const Point m = midpoint(a, arc);
      std::ostringstream msg;
      msg << "arc " << i << " near (" << m.x << ", " << m.y << ") only in the first graph";
      out.differences.push_back({DifferenceKind::ArcOnlyInA, static_cast<int>(i), m.x, m.y, msg.str()});
    }
  }
  for (std::size_t j = 0; j < b.arcs.size(); ++j) {
    if (b_used[j] || tiny(b, cb, b.arcs[j]) || beyond(b, b.arcs[j])) continue;
    const Arc& arc = b.arcs[j];
    const Point m = midpoint(b, arc);
    std::ostringstream msg;
    msg << "arc " << j << " near (" << m.x << ", " << m.y << ") only in the second graph";
    if (arc.left_site != kNone && arc.right_site != kNone && arc.left_site < static_cast<int>(b.sites.size()) &&
        arc.right_site < static_cast<int>(b.sites.size()))
      msg << " (between the regions of sites '" << b.sites[arc.left_site].id << "' and '"
          << b.sites[arc.right_site].id << "')";
    out.differences.push_back({DifferenceKind::ArcOnlyInB, static_cast<int>(j), m.x, m.y, msg.str()});
  }
  // Combinatorial differences that are geometrically nothing: a degenerate input (a tangency, a
  // node of degree four) may be drawn with another topology after any rounding, yet every point of
  // the unmatched node or arc lies on the other graph. Those are dropped. (Bounded effort: with very
  // many differences the graphs differ anyway and all are kept.)
  if (!out.differences.empty() && out.differences.size() <= 200) {
    std::optional<ArcProximity> near_a, near_b;  // built on first use
    std::vector<Difference> kept;
    for (const Difference& diff : out.differences) {
      const bool in_a = diff.kind == DifferenceKind::NodeOnlyInA || diff.kind == DifferenceKind::ArcOnlyInA;
      const Diagram& own = in_a ? a : b;
      std::optional<ArcProximity>& other = in_a ? near_b : near_a;
      if (!other) other.emplace(in_a ? b : a);
      std::vector<Point> points;
      if (diff.kind == DifferenceKind::NodeOnlyInA || diff.kind == DifferenceKind::NodeOnlyInB)
        points.push_back({own.nodes[diff.index].x, own.nodes[diff.index].y});
      else
        points = arc_samples(own, own.arcs[diff.index], scale);
      if (!std::all_of(points.begin(), points.end(), [&](Point q) { return other->near(q, scaled_tol(q.x, q.y)); }))
        kept.push_back(diff);
    }
    out.differences = std::move(kept);
  }
  return out;
}

}  // namespace covmap::recognition
