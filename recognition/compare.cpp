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


// Cells are hashed in unsigned arithmetic: a node 10^6 extents from the origin is ~10^13 cells
// out, and the signed product overflowed. Coordinates beyond 2^62 cells, infinite or NaN (a node of
// a degenerate input, recomputed) are clamped to the last cell before the conversion, which was
// undefined for them; whether such a node matches is still decided by its distance.
struct Grid {
  double cell;
  std::unordered_map<long long, std::vector<int>> buckets;
  static long long key(long long x, long long y) {
    return static_cast<long long>(static_cast<unsigned long long>(x) * 73856093ULL ^
                                  static_cast<unsigned long long>(y) * 19349663ULL);
  }
  long long ix(double v) const {
    constexpr double kLimit = 0x1p62;
    const double c = std::floor(v / cell);
    return static_cast<long long>(std::isnan(c) ? kLimit : std::clamp(c, -kLimit, kLimit));
  }
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
    s = p.param_of(q);
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
// lines) are kept apart and always tested. Without the grid the check would filter each difference
// against every arc, seconds for a few differences of a large diagram.
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

// The yardsticks of one comparison: the extent's size, the tolerance and the horizon derived from
// it, and the centre that distances to the horizon are measured from.
struct Measures {
  double scale = 1.0;
  double tol = 0.0;
  Point centre;
  double horizon = 0.0;

  // A node beyond the horizon (or none: an arc's end at infinity) counts as a point at infinity.
  bool far_node(const Diagram& d, int v) const {
    return v == kNone || std::hypot(d.nodes[v].x - centre.x, d.nodes[v].y - centre.y) > horizon;
  }
  // Far from the sites, positions of nodes and circles are sensitive to the sites' rounding in
  // proportion to their distance (nearly tangent bisectors): the tolerance at (x, y), scaled by its
  // distance from the centre in units of the extent.
  double scaled_tol(double x, double y) const {
    return tol * std::max(1.0, std::hypot(x - centre.x, y - centre.y) / scale);
  }
  // A curve's own numbers are known in proportion to their size (see scaled_tol).
  double curve_tol(const Arc& arc) const {
    if (const auto* c = std::get_if<Circle>(&arc.curve))
      return tol * std::max(1.0, (std::hypot(c->cx - centre.x, c->cy - centre.y) + c->r) / scale);
    return tol;
  }
};

// The extent: the central part of the first graph's nodes and full circles (core/extent.h) and both
// graphs' sites (not the second graph's nodes, which may hold the far artefacts the horizon is
// there to ignore). The first graph is the reference unless it has no arcs.
Measures comparison_measures(const Diagram& a, const Diagram& b, const CompareOptions& options) {
  const Diagram& reference = a.arcs.empty() ? b : a;
  const Box e = graph_extent(reference);
  double xmin = e.xmin, xmax = e.xmax, ymin = e.ymin, ymax = e.ymax;
  if (reference.arcs.empty() && reference.nodes.empty()) xmin = ymin = INFINITY, xmax = ymax = -INFINITY;
  for (const Diagram* d : {&a, &b})
    for (const auto& s : d->sites) {
      xmin = std::min(xmin, s.x), xmax = std::max(xmax, s.x);
      ymin = std::min(ymin, s.y), ymax = std::max(ymax, s.y);
    }
  Measures m;
  m.scale = std::isfinite(xmax - xmin) ? std::max(std::hypot(xmax - xmin, ymax - ymin), 1e-300) : 1.0;
  m.tol = options.relative_tolerance * m.scale;
  m.centre = {0.5 * (xmin + xmax), 0.5 * (ymin + ymax)};
  m.horizon = options.horizon * m.scale;
  return m;
}

// An arc beyond the horizon: both ends far (or at infinity) and its nearest point to the centre
// far too.
bool beyond_horizon(const Measures& m, const Diagram& d, const Arc& arc) {
  if (!m.far_node(d, arc.from) || !m.far_node(d, arc.to)) return false;
  const voronoi::ArcPathView p = voronoi::arc_path(arc, d.nodes);
  double s;
  if (p.circle) {
    s = p.param_of(m.centre);
    if (s < p.s0 || s > p.s1) return true;  // the nearest point is an end: far
  } else {
    s = std::clamp((m.centre.x - p.ox) * p.ux + (m.centre.y - p.oy) * p.uy, p.s0, p.s1);
  }
  const Point q = p.at(s);
  return std::hypot(q.x - m.centre.x, q.y - m.centre.y) > m.horizon;
}

// Nodes closer than tol within one graph are one node (a node of degree four may be recomputed
// as two of degree three joined by an arc shorter than the tolerance): per node, the
// representative of its cluster.
std::vector<int> node_clusters(const Diagram& d, double tol) {
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
}

// An arc inside one cluster that is itself that short (it is ignored); a long arc between two
// clustered nodes (a circle nearly touching itself there) is a loop through the cluster and is
// compared.
bool tiny(const Diagram& d, const std::vector<int>& clusters, const Arc& arc, double tol) {
  if (arc.from == kNone || arc.to == kNone || arc.from == arc.to || clusters[arc.from] != clusters[arc.to])
    return false;
  const voronoi::ArcPathView p = voronoi::arc_path(arc, d.nodes);
  const double length = p.circle ? p.r * (p.s1 - p.s0) : std::abs(p.s1 - p.s0);
  return length <= 2 * tol;
}

// The nodes that take part in the comparison: cluster representatives within the horizon.
bool compared(const Measures& m, const Diagram& d, const std::vector<int>& clusters, std::size_t i) {
  return clusters[i] == static_cast<int>(i) && !m.far_node(d, static_cast<int>(i));
}

// Matched nodes, both ways (kNone where unmatched).
struct NodeMatching {
  std::vector<int> a_to_b;
  std::vector<int> b_to_a;
};

// Each compared node of a to the nearest unused compared node of b within tol, through a hash grid
// of b's nodes. Returns the number of nodes matched.
std::size_t match_nodes_nearby(const Diagram& a, const Diagram& b, const std::vector<int>& ca,
                               const std::vector<int>& cb, const Measures& m, NodeMatching& match) {
  Grid grid{m.tol, {}};
  for (std::size_t j = 0; j < b.nodes.size(); ++j)
    if (compared(m, b, cb, j)) grid.add(b.nodes[j].x, b.nodes[j].y, static_cast<int>(j));
  std::size_t matched = 0;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    if (!compared(m, a, ca, i)) continue;
    int best = kNone;
    double best_d = m.tol;
    grid.near(a.nodes[i].x, a.nodes[i].y, [&](int j) {
      const double dd = std::hypot(a.nodes[i].x - b.nodes[j].x, a.nodes[i].y - b.nodes[j].y);
      if (match.b_to_a[j] == kNone && dd <= best_d) best = j, best_d = dd;
    });
    if (best != kNone) {
      match.a_to_b[i] = best;
      match.b_to_a[best] = static_cast<int>(i);
      ++matched;
    }
  }
  return matched;
}

// A second chance for the nodes still unmatched, with the tolerance scaled by their distance from
// the centre (Measures::scaled_tol), by brute force over the unmatched nodes of b (skipped when
// that would take more than 4·10^6 distances). Returns the number of nodes matched.
std::size_t match_remaining_nodes(const Diagram& a, const Diagram& b, const std::vector<int>& ca,
                                  const std::vector<int>& cb, const Measures& m, NodeMatching& match) {
  std::vector<int> ua, ub;
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    if (match.a_to_b[i] == kNone && compared(m, a, ca, i)) ua.push_back(static_cast<int>(i));
  for (std::size_t j = 0; j < b.nodes.size(); ++j)
    if (match.b_to_a[j] == kNone && compared(m, b, cb, j)) ub.push_back(static_cast<int>(j));
  std::size_t matched = 0;
  if (ua.size() * ub.size() > 4000000) return matched;
  for (int i : ua) {
    int best = kNone;
    double best_d = m.scaled_tol(a.nodes[i].x, a.nodes[i].y);
    for (int j : ub) {
      if (match.b_to_a[j] != kNone) continue;
      const double dd = std::hypot(a.nodes[i].x - b.nodes[j].x, a.nodes[i].y - b.nodes[j].y);
      if (dd <= best_d) best = j, best_d = dd;
    }
    if (best != kNone) {
      match.a_to_b[i] = best;
      match.b_to_a[best] = i;
      ++matched;
    }
  }
  return matched;
}

// Every compared node left unmatched, of a then of b, as a difference.
void report_unmatched_nodes(const Diagram& a, const Diagram& b, const std::vector<int>& ca,
                            const std::vector<int>& cb, const Measures& m, const NodeMatching& match,
                            std::vector<Difference>& differences) {
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    if (match.a_to_b[i] == kNone && compared(m, a, ca, i)) {
      std::ostringstream msg;
      msg << "node " << i << " at (" << a.nodes[i].x << ", " << a.nodes[i].y << ") only in the first graph";
      differences.push_back({DifferenceKind::NodeOnlyInA, static_cast<int>(i), a.nodes[i].x, a.nodes[i].y, msg.str()});
    }
  for (std::size_t j = 0; j < b.nodes.size(); ++j)
    if (match.b_to_a[j] == kNone && compared(m, b, cb, j)) {
      std::ostringstream msg;
      msg << "node " << j << " at (" << b.nodes[j].x << ", " << b.nodes[j].y << ") only in the second graph";
      differences.push_back({DifferenceKind::NodeOnlyInB, static_cast<int>(j), b.nodes[j].x, b.nodes[j].y, msg.str()});
    }
}

// Matched arcs: a's arcs that found a partner, which of b's arcs were taken, and a's compared arcs
// that found none (in index order).
struct ArcMatching {
  std::size_t matched = 0;
  std::vector<char> b_used;
  std::vector<int> only_in_a;
};

// The unordered pair of an arc's end nodes (in b's numbering, kNone for infinity) as one key.
long long end_pair_key(int u, int v) {
  if (u > v) std::swap(u, v);
  return (static_cast<long long>(u) + 2) * 4000000007LL + (v + 2);
}

// Arcs: each arc of a (not tiny, not beyond the horizon) to an unused arc of b with the same
// matched end nodes and the same curve within Measures::curve_tol.
ArcMatching match_arcs(const Diagram& a, const Diagram& b, const std::vector<int>& ca, const std::vector<int>& cb,
                       const Measures& m, const std::vector<int>& a_to_b) {
  // Arc ends in b's node numbering: cluster representatives, far nodes as infinity.
  auto b_end = [&](int v) { return m.far_node(b, v) ? kNone : cb[v]; };
  std::unordered_map<long long, std::vector<int>> b_arcs;
  for (std::size_t j = 0; j < b.arcs.size(); ++j)
    b_arcs[end_pair_key(b_end(b.arcs[j].from), b_end(b.arcs[j].to))].push_back(static_cast<int>(j));
  ArcMatching out;
  out.b_used.assign(b.arcs.size(), 0);
  for (std::size_t i = 0; i < a.arcs.size(); ++i) {
    const Arc& arc = a.arcs[i];
    if (tiny(a, ca, arc, m.tol) || beyond_horizon(m, a, arc)) continue;
    const bool from_inf = m.far_node(a, arc.from), to_inf = m.far_node(a, arc.to);
    const int u = from_inf ? kNone : a_to_b[ca[arc.from]];
    const int v = to_inf ? kNone : a_to_b[ca[arc.to]];
    bool matched = false;
    if ((from_inf || u != kNone) && (to_inf || v != kNone)) {
      auto it = b_arcs.find(end_pair_key(u, v));
      if (it != b_arcs.end())
        for (int j : it->second)
          if (!out.b_used[j] && same_curve(arc, b.arcs[j], m.curve_tol(arc))) {
            out.b_used[j] = 1;
            matched = true;
            ++out.matched;
            break;
          }
    }
    if (!matched) out.only_in_a.push_back(static_cast<int>(i));
  }
  return out;
}

// Every compared arc left unmatched, of a then of b, as a difference at its midpoint; an arc of b
// also names the sites whose regions it separates.
void report_unmatched_arcs(const Diagram& a, const Diagram& b, const std::vector<int>& cb, const Measures& m,
                           const ArcMatching& match, std::vector<Difference>& differences) {
  for (int i : match.only_in_a) {
    const Point mid = midpoint(a, a.arcs[i]);
    std::ostringstream msg;
    msg << "arc " << i << " near (" << mid.x << ", " << mid.y << ") only in the first graph";
    differences.push_back({DifferenceKind::ArcOnlyInA, i, mid.x, mid.y, msg.str()});
  }
  for (std::size_t j = 0; j < b.arcs.size(); ++j) {
    if (match.b_used[j] || tiny(b, cb, b.arcs[j], m.tol) || beyond_horizon(m, b, b.arcs[j])) continue;
    const Arc& arc = b.arcs[j];
    const Point mid = midpoint(b, arc);
    std::ostringstream msg;
    msg << "arc " << j << " near (" << mid.x << ", " << mid.y << ") only in the second graph";
    if (arc.left_site != kNone && arc.right_site != kNone && arc.left_site < static_cast<int>(b.sites.size()) &&
        arc.right_site < static_cast<int>(b.sites.size()))
      msg << " (between the regions of sites '" << b.sites[arc.left_site].id << "' and '"
          << b.sites[arc.right_site].id << "')";
    differences.push_back({DifferenceKind::ArcOnlyInB, static_cast<int>(j), mid.x, mid.y, msg.str()});
  }
}

// Combinatorial differences that are geometrically nothing: a degenerate input (a tangency, a
// node of degree four) may be drawn with another topology after any rounding, yet every point of
// the unmatched node or arc lies on the other graph. Those are dropped. (Bounded effort: with very
// many differences the graphs differ anyway and all are kept.)
std::vector<Difference> drop_differences_on_the_other_graph(const Diagram& a, const Diagram& b, const Measures& m,
                                                            std::vector<Difference> differences) {
  if (differences.empty() || differences.size() > 200) return differences;
  std::optional<ArcProximity> near_a, near_b;  // built on first use
  std::vector<Difference> kept;
  for (const Difference& diff : differences) {
    const bool in_a = diff.kind == DifferenceKind::NodeOnlyInA || diff.kind == DifferenceKind::ArcOnlyInA;
    const Diagram& own = in_a ? a : b;
    std::optional<ArcProximity>& other = in_a ? near_b : near_a;
    if (!other) other.emplace(in_a ? b : a);
    std::vector<Point> points;
    if (diff.kind == DifferenceKind::NodeOnlyInA || diff.kind == DifferenceKind::NodeOnlyInB)
      points.push_back({own.nodes[diff.index].x, own.nodes[diff.index].y});
    else
      points = arc_samples(own, own.arcs[diff.index], m.scale);
    if (!std::all_of(points.begin(), points.end(), [&](Point q) { return other->near(q, m.scaled_tol(q.x, q.y)); }))
      kept.push_back(diff);
  }
  return kept;
}

}  // namespace

const char* to_string(DifferenceKind kind) {
  switch (kind) {
    case DifferenceKind::NodeOnlyInA: return "NodeOnlyInA";
    case DifferenceKind::NodeOnlyInB: return "NodeOnlyInB";
    case DifferenceKind::ArcOnlyInA: return "ArcOnlyInA";
    case DifferenceKind::ArcOnlyInB: return "ArcOnlyInB";
    case DifferenceKind::FaceOnlyInB: return "FaceOnlyInB";
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
  const Measures m = comparison_measures(a, b, options);
  const std::vector<int> ca = node_clusters(a, m.tol), cb = node_clusters(b, m.tol);

  // Nodes: each cluster of a to the nearest unused cluster of b, within tol, then within the
  // tolerance scaled by the distance from the centre.
  NodeMatching nodes{std::vector<int>(a.nodes.size(), kNone), std::vector<int>(b.nodes.size(), kNone)};
  out.nodes_matched += match_nodes_nearby(a, b, ca, cb, m, nodes);
  out.nodes_matched += match_remaining_nodes(a, b, ca, cb, m, nodes);
  report_unmatched_nodes(a, b, ca, cb, m, nodes, out.differences);

  // Arcs: by their matched end nodes and their curve.
  const ArcMatching arcs = match_arcs(a, b, ca, cb, m, nodes.a_to_b);
  out.arcs_matched = arcs.matched;
  report_unmatched_arcs(a, b, cb, m, arcs, out.differences);

  out.differences = drop_differences_on_the_other_graph(a, b, m, std::move(out.differences));
  return out;
}

}  // namespace covmap::recognition
