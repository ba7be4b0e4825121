#include "cleaning/tolerances.h"
#include "cleaning/arc_graph.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "cleaning/curve_fit.h"
#include "core/parallel.h"

namespace covmap::cleaning {
namespace {


double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Points along a polyline that starts at `start`, every `step`, up to arc length `reach`.
void walk_polyline(Point start, std::span<const Point> path, double step, double reach, std::vector<Point>& out) {
  Point previous = start;
  double travelled = 0.0;
  for (const Point& next : path) {
    const double l = distance(previous, next);
    for (double t = step; t <= l && travelled + t <= reach; t += step)
      out.push_back({previous.x + (next.x - previous.x) * t / l, previous.y + (next.y - previous.y) * t / l});
    travelled += l;
    if (travelled > reach) return;
    out.push_back(next);
    previous = next;
  }
}

// The frame around a junction as a straight line, when it is one there.
bool frame_line(Point junction, const std::vector<const BoundaryChain*>& arriving,
                const std::vector<const BoundaryChain*>& leaving, double snap, Line& out) {
  const double reach = tolerance::kFrameLineRadius * snap;
  std::vector<Point> pts{junction};
  for (const BoundaryChain* c : leaving) walk_polyline(junction, c->points, snap, reach, pts);
  for (const BoundaryChain* c : arriving) {
    std::vector<Point> reversed(c->points.rbegin(), c->points.rend());
    walk_polyline(junction, reversed, snap, reach, pts);
  }
  if (pts.size() < 3) return false;
  double mx = 0.0, my = 0.0;
  for (const Point& p : pts) mx += p.x, my += p.y;
  mx /= static_cast<double>(pts.size()), my /= static_cast<double>(pts.size());
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (const Point& p : pts) sxx += (p.x - mx) * (p.x - mx), syy += (p.y - my) * (p.y - my), sxy += (p.x - mx) * (p.y - my);
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  out = Line{mx, my, std::cos(angle), std::sin(angle)};
  double worst = 0.0;
  for (const Point& p : pts) worst = std::max(worst, std::abs(distance_to(out, p)));
  return worst <= tolerance::kFrameLineDeviation * snap;
}

// Least-squares meeting point of the curves, by damped Gauss-Newton from `start`.
Point meeting_point(Point start, const std::vector<Curve>& curves, double snap) {
  Point p = start;
  for (int it = 0; it < tolerance::kMeetingIterations; ++it) {
    double a = 0.0, b = 0.0, c = 0.0, ga = 0.0, gb = 0.0;
    for (const Curve& curve : curves) {
      Point g;
      const double d = distance_to(curve, p, &g);
      a += g.x * g.x, b += g.x * g.y, c += g.y * g.y;
      ga += g.x * d, gb += g.y * d;
    }
    const double mu = tolerance::kMeetingDamping * (a + c);
    a += mu, c += mu;
    const double det = a * c - b * b;
    if (!(det > 0.0)) break;
    const Point step{-(c * ga - b * gb) / det, -(a * gb - b * ga) / det};
    p.x += step.x, p.y += step.y;
    if (std::hypot(step.x, step.y) < tolerance::kMeetingStep * snap) break;
  }
  return p;
}

void simplify_range(std::span<const Point> pts, std::size_t i, std::size_t j, double tol, std::vector<char>& keep) {
  // Iterative Douglas–Peucker (no recursion depth limit on long frames).
  std::vector<std::pair<std::size_t, std::size_t>> stack{{i, j}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    if (b <= a + 1) continue;
    const Point p = pts[a], q = pts[b];
    const double l = distance(p, q);
    double worst = -1.0;
    std::size_t at = a;
    for (std::size_t k = a + 1; k < b; ++k) {
      const double d = l > 0.0 ? std::abs((q.x - p.x) * (pts[k].y - p.y) - (q.y - p.y) * (pts[k].x - p.x)) / l
                               : distance(pts[k], p);
      if (d > worst) worst = d, at = k;
    }
    if (worst > tol) {
      keep[at] = 1;
      stack.push_back({a, at});
      stack.push_back({at, b});
    }
  }
}

// The winding of a polyline about a centre: positive when it runs counter-clockwise.
double winding(std::span<const Point> pts, Point centre) {
  double w = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const Point a = pts[k], b = pts[k + 1];
    w += (a.x - centre.x) * (b.y - a.y) - (a.y - centre.y) * (b.x - a.x);
  }
  return w;
}

// A non-frame arc from node `from` to node `to` along `pts` (which include both ends).
Arc boundary_arc(const BoundaryChain& chain, std::span<const Point> pts, int from, int to,
                 const std::vector<Node>& nodes, double huber) {
  Arc arc;
  arc.from = from;
  arc.to = to;
  arc.left_site = chain.sensor_a;
  arc.right_site = chain.sensor_b;
  if (from == kNone) {
    arc.curve = chain.fit.curve;
  } else {
    const Point p{nodes[from].x, nodes[from].y}, q{nodes[to].x, nodes[to].y};
    const std::span<const Point> inner = pts.size() > 2 ? pts.subspan(1, pts.size() - 2) : std::span<const Point>{};
    arc.curve = fit_through(inner, p, q, chain.fit.curve, huber);
  }
  if (const auto* c = std::get_if<Circle>(&arc.curve)) arc.ccw = winding(pts, {c->cx, c->cy}) >= 0.0;
  return arc;
}

}  // namespace

std::size_t refine_junctions(std::vector<Point>& junctions, const std::vector<BoundaryChain>& chains, double snap) {
  std::vector<std::vector<std::size_t>> at(junctions.size());
  for (std::size_t c = 0; c < chains.size(); ++c) {
    if (chains[c].from != kNone) at[chains[c].from].push_back(c);
    if (chains[c].to != kNone && chains[c].to != chains[c].from) at[chains[c].to].push_back(c);
  }
  std::size_t moved = 0;
  for (std::size_t j = 0; j < junctions.size(); ++j) {
    std::vector<Curve> curves;
    std::vector<const BoundaryChain*> arriving, leaving;
    for (std::size_t c : at[j]) {
      const BoundaryChain& chain = chains[c];
      if (chain.sensor_b != kNone) {
        curves.push_back(chain.fit.curve);
      } else {
        if (chain.to == static_cast<int>(j)) arriving.push_back(&chain);
        if (chain.from == static_cast<int>(j)) leaving.push_back(&chain);
      }
    }
    if (curves.empty()) continue;
    Line frame;
    if (!arriving.empty() || !leaving.empty()) {
      if (frame_line(junctions[j], arriving, leaving, snap, frame)) curves.push_back(frame);
    }
    const Point p = meeting_point(junctions[j], curves, snap);
    if (distance(p, junctions[j]) <= tolerance::kNodeSnapRadius * snap && std::isfinite(p.x) && std::isfinite(p.y)) {
      if (p.x != junctions[j].x || p.y != junctions[j].y) ++moved;
      junctions[j] = p;
    }
  }
  return moved;
}

std::size_t finish_chains(CleanedMap& map, const std::vector<Point>& raw, double snap) {
  const auto clearance = [&](int j) {
    const Point before = raw[static_cast<std::size_t>(j)], now = map.junctions[static_cast<std::size_t>(j)];
    return tolerance::kJunctionClearance * snap + distance(before, now);
  };
  std::size_t frames = 0;
  for (BoundaryChain& chain : map.chains) {
    if (chain.from != kNone) {
      const Point a = map.junctions[static_cast<std::size_t>(chain.from)];
      const Point b = map.junctions[static_cast<std::size_t>(chain.to)];
      // (Not for a loop through one junction: it may not reach much farther than the clearance.)
      const double ra = chain.from == chain.to ? 0.0 : clearance(chain.from);
      const double rb = chain.from == chain.to ? 0.0 : clearance(chain.to);
      auto first = chain.points.begin(), last = chain.points.end();
      while (first != last && distance(*first, a) < ra) ++first;
      while (last != first && distance(*(last - 1), b) < rb) --last;
      std::vector<Point> kept{a};
      kept.insert(kept.end(), first, last);
      kept.push_back(b);
      chain.points = std::move(kept);
    }
    if (chain.sensor_b == kNone) {
      const double tol = tolerance::kFrameSimplify * snap;
      chain.points = chain.from == kNone ? simplify_closed(chain.points, tol) : simplify_open(chain.points, tol);
      ++frames;
    }
  }
  return frames;
}

std::vector<Point> simplify_open(std::span<const Point> points, double tol) {
  if (points.size() <= 2) return {points.begin(), points.end()};
  std::vector<char> keep(points.size(), 0);
  keep.front() = keep.back() = 1;
  simplify_range(points, 0, points.size() - 1, tol, keep);
  std::vector<Point> out;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (keep[k]) out.push_back(points[k]);
  return out;
}

std::vector<Point> simplify_closed(std::span<const Point> points, double tol) {
  if (points.size() <= 3) return {points.begin(), points.end()};
  // Split at the first vertex and the vertex farthest from it; keep a third so the ring stays a
  // polygon however straight it is.
  std::size_t far = 1;
  for (std::size_t k = 1; k < points.size(); ++k)
    if (distance(points[k], points[0]) > distance(points[far], points[0])) far = k;
  std::vector<Point> path(points.begin(), points.end());
  path.push_back(points[0]);
  std::vector<char> keep(path.size(), 0);
  keep[0] = keep[far] = keep.back() = 1;
  simplify_range(path, 0, far, tol, keep);
  simplify_range(path, far, path.size() - 1, tol, keep);
  if (std::count(keep.begin(), keep.end() - 1, 1) < 3) {
    std::size_t third = 1;
    double best = -1.0;
    for (std::size_t k = 1; k + 1 < path.size(); ++k) {
      if (k == far) continue;
      const double d = std::abs(distance_to(Line{path[0].x, path[0].y, path[far].x - path[0].x, path[far].y - path[0].y}, path[k]));
      if (d > best) best = d, third = k;
    }
    keep[third] = 1;
  }
  std::vector<Point> out;
  for (std::size_t k = 0; k + 1 < path.size(); ++k)
    if (keep[k]) out.push_back(path[k]);
  return out;
}

void build_graph(CleanedMap& map, double snap, double huber, int threads) {
  auto& g = map.graph;
  g.nodes.clear();
  g.arcs.clear();
  map.arc_chain.clear();
  for (const Point& j : map.junctions) g.nodes.push_back({j.x, j.y});
  const auto add_node = [&](Point p) {
    g.nodes.push_back({p.x, p.y});
    return static_cast<int>(g.nodes.size()) - 1;
  };
  const auto add_arc = [&](Arc arc, std::size_t chain) {
    g.arcs.push_back(std::move(arc));
    map.arc_chain.push_back(static_cast<int>(chain));
  };
  // Non-frame arcs are fitted (fit_through) after every node is placed, on the threads, each into
  // its own slot of g.arcs: the nodes and the arcs' order are settled first, in chain order.
  struct BoundaryArc {
    std::size_t arc = 0, chain = 0;
    int from = kNone, to = kNone;
    std::vector<Point> half;  // a half of a loop through one junction; empty: the chain's points
  };
  std::vector<BoundaryArc> boundary;
  const auto add_boundary_arc = [&](std::size_t chain, int from, int to, std::vector<Point> half) {
    boundary.push_back({g.arcs.size(), chain, from, to, std::move(half)});
    add_arc(Arc{}, chain);
  };
  const double tiny = tolerance::kTouching * snap;

  for (std::size_t c = 0; c < map.chains.size(); ++c) {
    const BoundaryChain& chain = map.chains[c];
    const std::vector<Point>& pts = chain.points;
    if (chain.sensor_b == kNone) {
      // Frame: straight segments between consecutive vertices; interior vertices become nodes.
      const bool loop = chain.from == kNone;
      std::vector<int> ids;
      for (std::size_t k = 0; k < pts.size(); ++k) {
        if (!loop && k == 0) ids.push_back(chain.from);
        else if (!loop && k + 1 == pts.size()) ids.push_back(chain.to);
        else if (!ids.empty() && distance(pts[k], {g.nodes[ids.back()].x, g.nodes[ids.back()].y}) <= tiny) continue;
        else ids.push_back(add_node(pts[k]));
      }
      if (loop && ids.size() >= 2) ids.push_back(ids.front());
      for (std::size_t k = 0; k + 1 < ids.size(); ++k) {
        const Node a = g.nodes[ids[k]], b = g.nodes[ids[k + 1]];
        const double l = std::hypot(b.x - a.x, b.y - a.y);
        if (!(l > 0.0)) continue;
        Arc arc;
        arc.from = ids[k];
        arc.to = ids[k + 1];
        arc.curve = Line{a.x, a.y, (b.x - a.x) / l, (b.y - a.y) / l};
        arc.left_site = chain.sensor_a;
        arc.right_site = kNone;
        arc.frame = true;
        add_arc(std::move(arc), c);
      }
      continue;
    }
    if (chain.from == kNone) {  // closed loop: the fitted circle itself
      add_boundary_arc(c, kNone, kNone, {});
      continue;
    }
    if (chain.from != chain.to) {
      add_boundary_arc(c, chain.from, chain.to, {});
      continue;
    }
    // A loop through one junction: split at its point farthest from the junction (moved onto the
    // fitted curve), so that each half runs between two distinct nodes.
    std::size_t far = pts.size() / 2;
    for (std::size_t k = 1; k + 1 < pts.size(); ++k)
      if (distance(pts[k], pts.front()) > distance(pts[far], pts.front())) far = k;
    Point grad;
    const double d = distance_to(chain.fit.curve, pts[far], &grad);
    const int middle = add_node({pts[far].x - d * grad.x, pts[far].y - d * grad.y});
    std::vector<Point> first(pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(far) + 1);
    std::vector<Point> second(pts.begin() + static_cast<std::ptrdiff_t>(far), pts.end());
    first.back() = second.front() = {g.nodes[middle].x, g.nodes[middle].y};
    add_boundary_arc(c, chain.from, middle, std::move(first));
    add_boundary_arc(c, middle, chain.to, std::move(second));
  }
  parallel_items(boundary.size(), threads, [&](std::size_t k) {
    const BoundaryArc& b = boundary[k];
    const BoundaryChain& chain = map.chains[b.chain];
    const std::span<const Point> pts = b.half.empty() ? std::span<const Point>(chain.points) : std::span<const Point>(b.half);
    g.arcs[b.arc] = boundary_arc(chain, pts, b.from, b.to, g.nodes, huber);
  });
}

}  // namespace covmap::cleaning
