#include "recognition/compare.h"

#include <cmath>
#include <sstream>
#include <unordered_map>

#include "voronoi/arc_path.h"

namespace covmap::recognition {
namespace {

using voronoi::Arc;
using voronoi::Diagram;
using voronoi::kNone;

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

voronoi::Point midpoint(const Diagram& d, const Arc& a) {
  const voronoi::ArcPathView p = voronoi::arc_path(a, d.nodes);
  const double s = std::isfinite(p.s0) && std::isfinite(p.s1) ? 0.5 * (p.s0 + p.s1)
                   : std::isfinite(p.s0)                       ? p.s0 + 1.0
                   : std::isfinite(p.s1)                       ? p.s1 - 1.0
                                                               : 0.0;
  return p.at(s);
}

bool same_curve(const Arc& a, const Arc& b, double tol) {
  const auto* ca = std::get_if<voronoi::Circle>(&a.curve);
  const auto* cb = std::get_if<voronoi::Circle>(&b.curve);
  if (ca && cb)
    return std::hypot(ca->cx - cb->cx, ca->cy - cb->cy) <= tol && std::abs(ca->r - cb->r) <= tol;
  if (!ca && !cb) {
    const auto& la = std::get<voronoi::Line>(a.curve);
    const auto& lb = std::get<voronoi::Line>(b.curve);
    const double na = std::hypot(la.dx, la.dy), nb = std::hypot(lb.dx, lb.dy);
    const double cross = (la.dx * lb.dy - la.dy * lb.dx) / (na * nb);
    const double offset = std::abs((lb.x - la.x) * la.dy - (lb.y - la.y) * la.dx) / na;
    return std::abs(cross) <= 1e-9 && offset <= tol;
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
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const Diagram* d : {&a, &b})
    for (const auto& n : d->nodes) {
      xmin = std::min(xmin, n.x), xmax = std::max(xmax, n.x);
      ymin = std::min(ymin, n.y), ymax = std::max(ymax, n.y);
    }
  for (const Diagram* d : {&a, &b})
    for (const auto& s : d->sites) {
      xmin = std::min(xmin, s.x), xmax = std::max(xmax, s.x);
      ymin = std::min(ymin, s.y), ymax = std::max(ymax, s.y);
    }
  const double scale = std::isfinite(xmax - xmin) ? std::max(std::hypot(xmax - xmin, ymax - ymin), 1e-300) : 1.0;
  const double tol = options.relative_tolerance * scale;

  // Nodes: each node of a to the nearest unused node of b within tol.
  Grid grid{tol, {}};
  for (std::size_t j = 0; j < b.nodes.size(); ++j) grid.add(b.nodes[j].x, b.nodes[j].y, static_cast<int>(j));
  std::vector<int> a_to_b(a.nodes.size(), kNone), b_to_a(b.nodes.size(), kNone);
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
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
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    if (a_to_b[i] == kNone) {
      std::ostringstream m;
      m << "node " << i << " at (" << a.nodes[i].x << ", " << a.nodes[i].y << ") only in the first graph";
      out.differences.push_back({DifferenceKind::NodeOnlyInA, static_cast<int>(i), a.nodes[i].x, a.nodes[i].y, m.str()});
    }
  for (std::size_t j = 0; j < b.nodes.size(); ++j)
    if (b_to_a[j] == kNone) {
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
  for (std::size_t j = 0; j < b.arcs.size(); ++j) b_arcs[key(b.arcs[j].from, b.arcs[j].to)].push_back(static_cast<int>(j));
  std::vector<char> b_used(b.arcs.size(), 0);
  for (std::size_t i = 0; i < a.arcs.size(); ++i) {
    const Arc& arc = a.arcs[i];
    const int u = arc.from == kNone ? kNone : a_to_b[arc.from];
    const int v = arc.to == kNone ? kNone : a_to_b[arc.to];
    bool matched = false;
    if ((arc.from == kNone || u != kNone) && (arc.to == kNone || v != kNone)) {
      auto it = b_arcs.find(key(u, v));
      if (it != b_arcs.end())
        for (int j : it->second)
          if (!b_used[j] && same_curve(arc, b.arcs[j], tol)) {
            b_used[j] = 1;
            matched = true;
            ++out.arcs_matched;
            break;
          }
    }
    if (!matched) {
      const voronoi::Point m = midpoint(a, arc);
      std::ostringstream msg;
      msg << "arc " << i << " near (" << m.x << ", " << m.y << ") only in the first graph";
      out.differences.push_back({DifferenceKind::ArcOnlyInA, static_cast<int>(i), m.x, m.y, msg.str()});
    }
  }
  for (std::size_t j = 0; j < b.arcs.size(); ++j) {
    if (b_used[j]) continue;
    const Arc& arc = b.arcs[j];
    const voronoi::Point m = midpoint(b, arc);
    std::ostringstream msg;
    msg << "arc " << j << " near (" << m.x << ", " << m.y << ") only in the second graph";
    if (arc.left_site != kNone && arc.right_site != kNone && arc.left_site < static_cast<int>(b.sites.size()) &&
        arc.right_site < static_cast<int>(b.sites.size()))
      msg << " (between the regions of sites '" << b.sites[arc.left_site].id << "' and '"
          << b.sites[arc.right_site].id << "')";
    out.differences.push_back({DifferenceKind::ArcOnlyInB, static_cast<int>(j), m.x, m.y, msg.str()});
  }
  return out;
}

}  // namespace covmap::recognition
