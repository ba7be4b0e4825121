// clean_coverage_map against independent oracles. Maps are made here from known weighted sites:
// a best-server raster by brute force (argmin |p − s| / w over bin centres), polygonized by a
// tiny boundary tracer of this file, optionally jittered per sensor and rounded. The cleaned map
// is then checked against the raster (which cells touch, which side is which) and against the
// exact MWVD of the sites, clipped to the map's frame (junctions vs diagram nodes, fitted curves
// vs Apollonius circles).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <variant>
#include <utility>
#include <vector>

#include "cleaning/map_cleaning.h"
#include "core/point_in_polygon.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::cleaning {
namespace {


constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------
// Maps from known sites.

struct Raster {
  double x0 = 0.0, y0 = 0.0, bin = 1.0;
  int nx = 0, ny = 0;
  std::vector<int> label;  // row-major, kNone: not covered
  int at(int i, int j) const { return i < 0 || j < 0 || i >= nx || j >= ny ? kNone : label[static_cast<std::size_t>(j) * nx + i]; }
  int at(Point p) const {
    return at(static_cast<int>(std::floor((p.x - x0) / bin)), static_cast<int>(std::floor((p.y - y0) / bin)));
  }
};

// Brute force best server; `covered(i, j)` false leaves a bin uncovered.
Raster rasterize(const std::vector<Site>& sites, double bin, int nx, int ny,
                 const std::function<bool(int, int)>& covered = {}) {
  Raster r;
  r.bin = bin, r.nx = nx, r.ny = ny;
  r.label.assign(static_cast<std::size_t>(nx) * ny, kNone);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (covered && !covered(i, j)) continue;
      const double x = (i + 0.5) * bin, y = (j + 0.5) * bin;
      double best = std::numeric_limits<double>::infinity();
      int who = kNone;
      for (std::size_t s = 0; s < sites.size(); ++s) {
        // (|p − s| / w)², which orders the sites the same way.
        const double dx = x - sites[s].x, dy = y - sites[s].y;
        const double d = (dx * dx + dy * dy) / (sites[s].weight * sites[s].weight);
        if (d < best) best = d, who = static_cast<int>(s);
      }
      r.label[static_cast<std::size_t>(j) * nx + i] = who;
    }
  return r;
}

struct Corner {
  int i = 0, j = 0;
  auto operator<=>(const Corner&) const = default;
};

struct TraceOptions {
  bool simplify = true;     // keep only the staircase's corners
  double jitter = 0.0;      // each corner moved by U(-jitter, jitter) per axis, per sensor
  double round_to = 0.0;    // coordinates rounded to multiples of this (0: not rounded)
  std::uint64_t seed = 1;
};

// Twice the signed area of a ring of corners.
long long twice_area(const std::vector<Corner>& ring) {
  long long a = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Corner p = ring[k], q = ring[(k + 1) % ring.size()];
    a += static_cast<long long>(p.i) * q.j - static_cast<long long>(q.i) * p.j;
  }
  return a;
}

// Even-odd containment of the point (x, y) (never on a grid line here: edge midpoints are).
bool contains(const std::vector<Corner>& ring, double x, double y) {
  std::vector<Point> points;
  for (const Corner& c : ring) points.push_back({static_cast<double>(c.i), static_cast<double>(c.j)});
  return inside_ring(points, {x, y});
}

// Every label's bins as polygons with holes: boundary edges with the label on their left, linked
// into rings taking the leftmost turn at a corner shared by two diagonal bins (4-connected cells).
// `sensor_of` names each label's sensor (several labels may share one: pieces of one region).
std::vector<CoverageCell> polygonize(const Raster& r, const std::vector<std::string>& sensor_of,
                                     const TraceOptions& o = {}) {
  std::vector<CoverageCell> cells;
  const int labels = static_cast<int>(sensor_of.size());
  for (int label = 0; label < labels; ++label) {
    std::vector<std::pair<Corner, Corner>> edges;
    for (int j = 0; j < r.ny; ++j)
      for (int i = 0; i < r.nx; ++i) {
        if (r.at(i, j) != label) continue;
        if (r.at(i, j - 1) != label) edges.push_back({{i, j}, {i + 1, j}});
        if (r.at(i + 1, j) != label) edges.push_back({{i + 1, j}, {i + 1, j + 1}});
        if (r.at(i, j + 1) != label) edges.push_back({{i + 1, j + 1}, {i, j + 1}});
        if (r.at(i - 1, j) != label) edges.push_back({{i, j + 1}, {i, j}});
      }
    if (edges.empty()) continue;
    std::map<Corner, std::vector<std::size_t>> leaving;
    for (std::size_t e = 0; e < edges.size(); ++e) leaving[edges[e].first].push_back(e);
    std::vector<char> used(edges.size(), 0);
    std::vector<std::vector<Corner>> rings;
    for (std::size_t start = 0; start < edges.size(); ++start) {
      if (used[start]) continue;
      std::vector<Corner> ring;
      std::size_t e = start;
      do {
        used[e] = 1;
        ring.push_back(edges[e].first);
        const Corner v = edges[e].second;
        const int dx = v.i - edges[e].first.i, dy = v.j - edges[e].first.j;
        std::size_t next = edges.size();
        int best_turn = -2;
        for (std::size_t f : leaving[v]) {
          const int ex = edges[f].second.i - v.i, ey = edges[f].second.j - v.j;
          const int turn = dx * ey - dy * ex;  // +1 left, 0 straight, -1 right
          if (dx * ex + dy * ey < 0) continue;  // never back
          if (turn > best_turn) best_turn = turn, next = f;
        }
        e = next;
      } while (e != start && e < edges.size());
      if (o.simplify) {
        std::vector<Corner> kept;
        for (std::size_t k = 0; k < ring.size(); ++k) {
          const Corner a = ring[(k + ring.size() - 1) % ring.size()], b = ring[k], c = ring[(k + 1) % ring.size()];
          if ((b.i - a.i) * (c.j - b.j) - (b.j - a.j) * (c.i - b.i) != 0) kept.push_back(b);
        }
        ring = kept;
      }
      rings.push_back(ring);
    }
    // Holes (clockwise) go to the smallest outer ring around them.
    std::vector<CellPolygon> polygons;
    std::vector<std::size_t> outer_ids;
    std::vector<long long> outer_area;
    for (const auto& ring : rings)
      if (twice_area(ring) > 0) outer_ids.push_back(polygons.size()), polygons.emplace_back(), outer_area.push_back(twice_area(ring));
    const std::string& sensor = sensor_of[static_cast<std::size_t>(label)];
    const std::uint64_t sensor_hash = std::hash<std::string>{}(sensor);
    const auto world = [&](Corner c) {
      Point p{r.x0 + c.i * r.bin, r.y0 + c.j * r.bin};
      if (o.jitter > 0.0) {
        std::mt19937_64 rng(o.seed ^ (sensor_hash * 0x9E3779B97F4A7C15ULL) ^
                            (static_cast<std::uint64_t>(c.i) * 0xC2B2AE3D27D4EB4FULL) ^
                            (static_cast<std::uint64_t>(c.j) * 0x165667B19E3779F9ULL));
        std::uniform_real_distribution<double> u(-o.jitter, o.jitter);
        p.x += u(rng);
        p.y += u(rng);
      }
      if (o.round_to > 0.0) p.x = std::round(p.x / o.round_to) * o.round_to, p.y = std::round(p.y / o.round_to) * o.round_to;
      return p;
    };
    const auto to_world = [&](const std::vector<Corner>& ring) {
      Ring out;
      for (const Corner& c : ring) out.push_back(world(c));
      return out;
    };
    std::size_t k = 0;
    for (const auto& ring : rings)
      if (twice_area(ring) > 0) polygons[k++].outer = to_world(ring);
    for (const auto& ring : rings) {
      if (twice_area(ring) > 0) continue;
      const double mx = 0.5 * (ring[0].i + ring[1].i), my = 0.5 * (ring[0].j + ring[1].j);
      std::size_t best = polygons.size();
      k = 0;
      for (const auto& outer : rings) {
        if (twice_area(outer) <= 0) continue;
        if (contains(outer, mx, my) && (best == polygons.size() || outer_area[k] < outer_area[best])) best = k;
        ++k;
      }
      if (best < polygons.size()) polygons[best].holes.push_back(to_world(ring));
    }
    cells.push_back({sensor, label, polygons});
  }
  return cells;
}

// "s7" for site 7 (built with append: GCC 12 warns falsely about "s" + std::to_string(k)).
std::string site_name(long long k) { return std::string("s").append(std::to_string(k)); }

std::vector<std::string> names(std::size_t n) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < n; ++k) out.push_back(site_name(static_cast<long long>(k)));
  return out;
}

// ---------------------------------------------------------------------------------------------
// Oracles.

// Pairs of labels sharing bin edges, with how many.
std::map<std::pair<int, int>, int> raster_neighbours(const Raster& r) {
  std::map<std::pair<int, int>, int> out;
  for (int j = 0; j < r.ny; ++j)
    for (int i = 0; i < r.nx; ++i) {
      const int a = r.at(i, j);
      for (const int b : {r.at(i + 1, j), r.at(i, j + 1)})
        if (a != kNone && b != kNone && a != b) ++out[{std::min(a, b), std::max(a, b)}];
    }
  return out;
}

Curve bisector(const Site& a, const Site& b) {
  if (a.weight == b.weight) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    return Line{0.5 * (a.x + b.x), 0.5 * (a.y + b.y), -dy, dx};
  }
  const double wa2 = a.weight * a.weight, wb2 = b.weight * b.weight;
  return Circle{(wa2 * b.x - wb2 * a.x) / (wa2 - wb2), (wa2 * b.y - wb2 * a.y) / (wa2 - wb2),
                a.weight * b.weight * std::hypot(a.x - b.x, a.y - b.y) / std::abs(wa2 - wb2)};
}

double distance(const Curve& curve, Point p) {
  if (const auto* c = std::get_if<Circle>(&curve)) return std::hypot(p.x - c->cx, p.y - c->cy) - c->r;
  const auto& l = std::get<Line>(curve);
  return ((p.x - l.x) * l.dy - (p.y - l.y) * l.dx) / std::hypot(l.dx, l.dy);
}

// The foot of p on a curve.
Point foot(const Curve& curve, Point p) {
  if (const auto* c = std::get_if<Circle>(&curve)) {
    const double d = std::hypot(p.x - c->cx, p.y - c->cy);
    return {c->cx + (p.x - c->cx) * c->r / d, c->cy + (p.y - c->cy) * c->r / d};
  }
  const auto& l = std::get<Line>(curve);
  const double n = std::hypot(l.dx, l.dy), t = ((p.x - l.x) * l.dx + (p.y - l.y) * l.dy) / (n * n);
  return {l.x + t * l.dx, l.y + t * l.dy};
}

// Nodes of the sites' MWVD clipped to `frame` where three or more regions (or two and the
// outside) meet: the junctions a cleaned map should have.
std::vector<Point> true_junctions(const std::vector<Site>& sites, const std::vector<Point>& frame) {
  const Diagram d = voronoi::clip_diagram(voronoi::build_diagram(sites), frame);
  std::vector<int> boundary(d.nodes.size(), 0), framed(d.nodes.size(), 0);
  for (const auto& a : d.arcs)
    for (const int n : {a.from, a.to}) {
      if (n == kNone) continue;
      (a.frame ? framed : boundary)[static_cast<std::size_t>(n)]++;
    }
  std::vector<Point> out;
  for (std::size_t n = 0; n < d.nodes.size(); ++n)
    if (boundary[n] >= 3 || (boundary[n] >= 1 && framed[n] >= 1)) out.push_back({d.nodes[n].x, d.nodes[n].y});
  return out;
}

double nearest(const std::vector<Point>& points, Point p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Point& q : points) best = std::min(best, std::hypot(p.x - q.x, p.y - q.y));
  return best;
}

double min_separation(const std::vector<Point>& points) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      best = std::min(best, std::hypot(points[i].x - points[j].x, points[i].y - points[j].y));
  return best;
}

int sensor_index(const CleanedMap& m, const std::string& id) {
  const auto it = std::find(m.sensors.begin(), m.sensors.end(), id);
  return it == m.sensors.end() ? kNone : static_cast<int>(it - m.sensors.begin());
}

// Structural invariants every cleaned map must satisfy.
void expect_consistent(const CleanedMap& m) {
  const double scale = std::max(1.0, m.report.snap_distance);
  ASSERT_EQ(m.arc_chain.size(), m.graph.arcs.size());
  ASSERT_GE(m.graph.nodes.size(), m.junctions.size());
  std::vector<int> ends(m.junctions.size(), 0);
  for (const BoundaryChain& c : m.chains) {
    ASSERT_GE(c.sensor_a, 0);
    if (c.sensor_b != kNone) {
      EXPECT_LT(c.sensor_a, c.sensor_b);
    }
    ASSERT_EQ(c.from == kNone, c.to == kNone);
    if (c.from != kNone) {
      ASSERT_LT(static_cast<std::size_t>(c.from), m.junctions.size());
      ASSERT_LT(static_cast<std::size_t>(c.to), m.junctions.size());
      ++ends[static_cast<std::size_t>(c.from)];
      ++ends[static_cast<std::size_t>(c.to)];
      ASSERT_GE(c.points.size(), 2u);
      EXPECT_EQ(c.points.front().x, m.junctions[static_cast<std::size_t>(c.from)].x);
      EXPECT_EQ(c.points.back().y, m.junctions[static_cast<std::size_t>(c.to)].y);
    }
  }
  // A junction is where at least three boundaries (frame pieces included) end.
  for (std::size_t j = 0; j < ends.size(); ++j) EXPECT_GE(ends[j], 3) << "junction " << j;
  for (std::size_t a = 0; a < m.graph.arcs.size(); ++a) {
    const auto& arc = m.graph.arcs[a];
    const BoundaryChain& chain = m.chains[static_cast<std::size_t>(m.arc_chain[a])];
    EXPECT_EQ(arc.left_site, chain.sensor_a);
    EXPECT_EQ(arc.right_site, chain.sensor_b);
    EXPECT_EQ(arc.frame, chain.sensor_b == kNone);
    for (const int n : {arc.from, arc.to}) {
      if (n == kNone) continue;
      const Point p{m.graph.nodes[static_cast<std::size_t>(n)].x, m.graph.nodes[static_cast<std::size_t>(n)].y};
      EXPECT_LT(std::abs(distance(arc.curve, p)), 1e-7 * scale) << "arc " << a << " does not end on its curve";
    }
  }
  EXPECT_EQ(m.report.chains, m.chains.size());
  EXPECT_EQ(m.report.junctions, m.junctions.size());
}

// No two chain polylines cross (touching at shared junctions is fine). Quadratic: small maps only.
void expect_no_crossings(const CleanedMap& m) {
  struct Segment {
    Point a, b;
    std::size_t chain;
  };
  std::vector<Segment> segments;
  for (std::size_t c = 0; c < m.chains.size(); ++c) {
    const auto& pts = m.chains[c].points;
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) segments.push_back({pts[k], pts[k + 1], c});
    if (m.chains[c].from == kNone && pts.size() > 2) segments.push_back({pts.back(), pts.front(), c});
  }
  const auto orient = [](Point a, Point b, Point c) {
    const double v = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return v > 0 ? 1 : v < 0 ? -1 : 0;
  };
  std::size_t crossings = 0;
  for (std::size_t i = 0; i < segments.size(); ++i)
    for (std::size_t j = i + 1; j < segments.size(); ++j) {
      const Segment &s = segments[i], &t = segments[j];
      const int o1 = orient(s.a, s.b, t.a), o2 = orient(s.a, s.b, t.b);
      const int o3 = orient(t.a, t.b, s.a), o4 = orient(t.a, t.b, s.b);
      if (o1 * o2 < 0 && o3 * o4 < 0) {
        ++crossings;
        ADD_FAILURE() << "chains " << s.chain << " and " << t.chain << " cross near (" << s.a.x << ", " << s.a.y << ")";
      }
    }
  EXPECT_EQ(crossings, 0u);
}

struct Expectations {
  double junction_bins = 2.0;  // junctions within this many bins of the diagram's nodes
  double curve_bins = 1.0;     // fitted curves within this many bins of the true bisector
  int must_chain_edges = 6;    // raster pairs sharing this many bin edges must have a chain
};

// Checks a cleaned map of `sites` (sensor "sK" = site K) against its raster and diagram.
void expect_matches(const CleanedMap& m, const std::vector<Site>& sites, const Raster& r,
                    const std::vector<Point>& frame, const Expectations& e = {}) {
  expect_consistent(m);
  expect_no_crossings(m);
  const double b = r.bin;
  // Which sensors touch.
  const auto touching = raster_neighbours(r);
  std::set<std::pair<int, int>> chained;
  for (const BoundaryChain& c : m.chains) {
    if (c.sensor_b == kNone) continue;
    const int sa = std::stoi(m.sensors[static_cast<std::size_t>(c.sensor_a)].substr(1));
    const int sb = std::stoi(m.sensors[static_cast<std::size_t>(c.sensor_b)].substr(1));
    const std::pair<int, int> pair{std::min(sa, sb), std::max(sa, sb)};
    chained.insert(pair);
    EXPECT_TRUE(touching.count(pair)) << "chain between s" << pair.first << " and s" << pair.second
                                      << ", which share no boundary";
  }
  for (const auto& [pair, edges] : touching) {
    if (edges >= e.must_chain_edges) {
      EXPECT_TRUE(chained.count(pair)) << "no chain between s" << pair.first << " and s" << pair.second << " ("
                                       << edges << " shared bin edges)";
    }
  }

  // Junctions vs the diagram's nodes.
  const std::vector<Point> truth = true_junctions(sites, frame);
  EXPECT_EQ(m.junctions.size(), truth.size());
  for (const Point& t : truth) EXPECT_LE(nearest(m.junctions, t), e.junction_bins * b) << "node (" << t.x << ", " << t.y << ")";
  for (const Point& j : m.junctions) EXPECT_LE(nearest(truth, j), e.junction_bins * b) << "junction (" << j.x << ", " << j.y << ")";

  // Curves vs Apollonius circles, and sides vs the raster.
  for (std::size_t a = 0; a < m.graph.arcs.size(); ++a) {
    const auto& arc = m.graph.arcs[a];
    const BoundaryChain& chain = m.chains[static_cast<std::size_t>(m.arc_chain[a])];
    if (arc.frame) continue;
    const Site& sa = sites[static_cast<std::size_t>(std::stoi(m.sensors[static_cast<std::size_t>(chain.sensor_a)].substr(1)))];
    const Site& sb = sites[static_cast<std::size_t>(std::stoi(m.sensors[static_cast<std::size_t>(chain.sensor_b)].substr(1)))];
    const Curve truth_curve = bisector(sa, sb);
    double worst_fit = 0.0, worst_arc = 0.0;
    for (std::size_t k = 1; k + 1 < chain.points.size(); ++k) {
      worst_fit = std::max(worst_fit, std::abs(distance(truth_curve, foot(chain.fit.curve, chain.points[k]))));
      worst_arc = std::max(worst_arc, std::abs(distance(truth_curve, foot(arc.curve, chain.points[k]))));
    }
    EXPECT_LE(worst_fit, e.curve_bins * b) << sa.id << "|" << sb.id;
    EXPECT_LE(worst_arc, 2.0 * e.curve_bins * b) << sa.id << "|" << sb.id << " (arc through its nodes)";
  }
  for (const auto& arc : m.graph.arcs) {
    // The middle of each graph arc, along its own curve and direction: left site on the left.
    if (arc.from == kNone || arc.frame) continue;
    const auto& P = m.graph.nodes[static_cast<std::size_t>(arc.from)];
    const auto& Q = m.graph.nodes[static_cast<std::size_t>(arc.to)];
    Point mid, left_normal;
    if (const auto* c = std::get_if<Circle>(&arc.curve)) {
      const double ap = std::atan2(P.y - c->cy, P.x - c->cx), aq = std::atan2(Q.y - c->cy, Q.x - c->cx);
      const double sweep = std::fmod((arc.ccw ? aq - ap : ap - aq) + 4 * kPi, 2 * kPi);
      const double am = arc.ccw ? ap + sweep / 2 : ap - sweep / 2;
      mid = {c->cx + c->r * std::cos(am), c->cy + c->r * std::sin(am)};
      // Travelling counter-clockwise, the centre is on the left.
      left_normal = arc.ccw ? Point{-std::cos(am), -std::sin(am)} : Point{std::cos(am), std::sin(am)};
    } else {
      const auto& l = std::get<Line>(arc.curve);
      const double n = std::hypot(l.dx, l.dy);
      mid = {0.5 * (P.x + Q.x), 0.5 * (P.y + Q.y)};
      left_normal = {-l.dy / n, l.dx / n};
    }
    const Point left{mid.x + 1.5 * b * left_normal.x, mid.y + 1.5 * b * left_normal.y};
    const Point right{mid.x - 1.5 * b * left_normal.x, mid.y - 1.5 * b * left_normal.y};
    EXPECT_EQ(site_name(r.at(left)), m.sensors[static_cast<std::size_t>(arc.left_site)]);
    EXPECT_EQ(site_name(r.at(right)), m.sensors[static_cast<std::size_t>(arc.right_site)]);
  }
  for (const BoundaryChain& c : m.chains) {
    // The middle of the chain: sensor_a on the left, sensor_b (or nothing) on the right.
    if (c.points.size() < 2) continue;
    const std::size_t k = (c.points.size() - 1) / 2;
    const Point s = c.points[k], t = c.points[k + 1];
    const Point p{0.5 * (s.x + t.x), 0.5 * (s.y + t.y)};
    const double tx = t.x - s.x, ty = t.y - s.y;
    const double l = std::hypot(tx, ty);
    if (!(l > 0.0)) continue;
    const double off = c.sensor_b == kNone ? 0.5 * b : 1.5 * b;
    const Point left{p.x - ty / l * off, p.y + tx / l * off}, right{p.x + ty / l * off, p.y - tx / l * off};
    const int want_left = std::stoi(m.sensors[static_cast<std::size_t>(c.sensor_a)].substr(1));
    EXPECT_EQ(r.at(left), want_left) << "left of chain " << want_left << "|" << c.sensor_b;
    if (c.sensor_b != kNone) {
      EXPECT_EQ(r.at(right), std::stoi(m.sensors[static_cast<std::size_t>(c.sensor_b)].substr(1)));
    }
  }
}

std::vector<Point> rectangle(const Raster& r) {
  const double w = r.nx * r.bin, h = r.ny * r.bin;
  return {{r.x0, r.y0}, {r.x0 + w, r.y0}, {r.x0 + w, r.y0 + h}, {r.x0, r.y0 + h}};
}

// Seven sites of mixed weights in a 1000 m × 800 m map of 10 m bins; every diagram node is more
// than 6 bins from the next and from the frame's corners.
std::vector<Site> seven_sites() {
  return {{"s0", 200, 200, 1.0},  {"s1", 520, 140, 0.8}, {"s2", 820, 250, 0.9}, {"s3", 230, 590, 0.85},
          {"s4", 560, 450, 0.75}, {"s5", 820, 630, 1.0}, {"s6", 470, 710, 0.8}};
}

// ---------------------------------------------------------------------------------------------

TEST(MapCleaning, TestConfigurationIsWellSeparated) {
  // The oracle comparisons below need nodes farther apart than the cleaning's merge distances.
  const auto sites = seven_sites();
  const Raster r = rasterize(sites, 10.0, 100, 80);
  const auto truth = true_junctions(sites, rectangle(r));
  EXPECT_GE(truth.size(), 8u);
  EXPECT_GT(min_separation(truth), 6 * r.bin);
}

TEST(MapCleaning, RejectsAnEmptyMapAndBadOptions) {
  EXPECT_THROW(clean_coverage_map({}), std::invalid_argument);
  const std::vector<CoverageCell> no_polygons{{"a", 0, {}}};
  EXPECT_THROW(clean_coverage_map(no_polygons), std::invalid_argument);
  const std::vector<CoverageCell> one{{"a", 0, {{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}}}}};
  CleaningOptions bad;
  bad.line_preference = 0.5;
  EXPECT_THROW(clean_coverage_map(one, bad), std::invalid_argument);
  bad = {};
  bad.snap_distance = -1.0;
  EXPECT_THROW(clean_coverage_map(one, bad), std::invalid_argument);
  bad = {};
  bad.threads = 0;
  EXPECT_THROW(clean_coverage_map(one, bad), std::invalid_argument);
}

TEST(MapCleaning, SingleCellIsAFrameLoop) {
  // One sensor whose coverage ends 150 m out: a staircase disk of 10 m bins, all frame.
  const std::vector<Site> sites{{"s0", 200, 200, 1.0}};
  const Raster r = rasterize(sites, 10.0, 40, 40, [](int i, int j) {
    return std::hypot((i + 0.5) * 10.0 - 200.0, (j + 0.5) * 10.0 - 200.0) <= 150.0;
  });
  const CleanedMap m = clean_coverage_map(polygonize(r, names(1)));
  expect_consistent(m);
  EXPECT_DOUBLE_EQ(m.report.bin_size_estimate, 10.0);
  ASSERT_EQ(m.chains.size(), 1u);
  EXPECT_EQ(m.chains[0].sensor_b, kNone);
  EXPECT_EQ(m.chains[0].from, kNone);
  EXPECT_TRUE(m.junctions.empty());
  // Simplified (the staircase has ~120 corners), counter-clockwise with the cell on the left, and
  // within a bin of the staircase: the area stays that of the bins.
  EXPECT_LT(m.graph.arcs.size(), 40u);
  EXPECT_GE(m.graph.arcs.size(), 8u);
  double area = 0.0;
  for (const auto& a : m.graph.arcs) {
    EXPECT_TRUE(a.frame);
    EXPECT_EQ(a.left_site, 0);
    EXPECT_EQ(a.right_site, kNone);
    const auto& p = m.graph.nodes[static_cast<std::size_t>(a.from)];
    const auto& q = m.graph.nodes[static_cast<std::size_t>(a.to)];
    area += p.x * q.y - q.x * p.y;
  }
  const double bins = static_cast<double>(std::count(r.label.begin(), r.label.end(), 0));
  EXPECT_NEAR(area / 2, bins * 100.0, 0.05 * bins * 100.0);
}

TEST(MapCleaning, EstimatesTheBinSize) {
  const auto sites = seven_sites();
  const Raster r = rasterize(sites, 10.0, 100, 80);
  for (const bool simplify : {true, false}) {
    const CleanedMap m = clean_coverage_map(polygonize(r, names(sites.size()), {simplify}));
    EXPECT_DOUBLE_EQ(m.report.bin_size_estimate, 10.0) << "simplify " << simplify;
    EXPECT_DOUBLE_EQ(m.report.snap_distance, 5.0);
  }
  TraceOptions noisy;
  noisy.jitter = 1.0;
  noisy.round_to = 0.01;
  const CleanedMap m = clean_coverage_map(polygonize(r, names(sites.size()), noisy));
  EXPECT_NEAR(m.report.bin_size_estimate, 10.0, 1.0);
  // Not a raster: a 60-gon island in a square.
  Ring disk, hole;
  for (int k = 0; k < 60; ++k) disk.push_back({50 + 20 * std::cos(k * 2 * kPi / 60), 50 + 20 * std::sin(k * 2 * kPi / 60)});
  hole.assign(disk.rbegin(), disk.rend());
  const std::vector<CoverageCell> vector_map{{"a", 0, {{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {hole}}}},
                                             {"b", 1, {{disk, {}}}}};
  const CleanedMap v = clean_coverage_map(vector_map);
  EXPECT_EQ(v.report.bin_size_estimate, 0.0);
  EXPECT_GT(v.report.snap_distance, 0.0);
}

TEST(MapCleaning, ExactStaircasesMatchTheDiagram) {
  const auto sites = seven_sites();
  const Raster r = rasterize(sites, 10.0, 100, 80);
  const CleanedMap m = clean_coverage_map(polygonize(r, names(sites.size())));
  expect_matches(m, sites, r, rectangle(r));
  EXPECT_EQ(m.report.gaps_closed, 0u);
  EXPECT_EQ(m.report.overlaps_resolved, 0u);
  EXPECT_EQ(m.report.cells, sites.size());
  EXPECT_EQ(m.report.sensors, sites.size());
  EXPECT_GT(m.report.frame_chains, 0u);
}

TEST(MapCleaning, UnsimplifiedStaircasesMatchTheDiagram) {
  const auto sites = seven_sites();
  const Raster r = rasterize(sites, 10.0, 100, 80);
  const CleanedMap m = clean_coverage_map(polygonize(r, names(sites.size()), {false}));
  expect_matches(m, sites, r, rectangle(r));
}

TEST(MapCleaning, JitteredAndRoundedCopiesAreClosed) {
  // Each sensor's copy of a boundary moves independently by up to b/8 per axis (copies differ by
  // up to b/4), then coordinates are rounded to 0.5 m: gaps and overlaps everywhere.
  const auto sites = seven_sites();
  const Raster r = rasterize(sites, 10.0, 100, 80);
  TraceOptions o;
  o.jitter = 1.25;
  o.round_to = 0.5;
  o.seed = 11;
  const CleanedMap m = clean_coverage_map(polygonize(r, names(sites.size()), o));
  expect_matches(m, sites, r, rectangle(r));
  EXPECT_GT(m.report.gaps_closed, 0u);
  EXPECT_GT(m.report.overlaps_resolved, 0u);
  // Sampled on three threads, the rings give the same map (and the same against the diagram).
  CleaningOptions threaded;
  threaded.threads = 3;
  const CleanedMap t = clean_coverage_map(polygonize(r, names(sites.size()), o), threaded);
  expect_matches(t, sites, r, rectangle(r));
  ASSERT_EQ(t.chains.size(), m.chains.size());
  for (std::size_t c = 0; c < m.chains.size(); ++c) {
    ASSERT_EQ(t.chains[c].points.size(), m.chains[c].points.size()) << "chain " << c;
    for (std::size_t k = 0; k < m.chains[c].points.size(); ++k) {
      EXPECT_EQ(t.chains[c].points[k].x, m.chains[c].points[k].x);
      EXPECT_EQ(t.chains[c].points[k].y, m.chains[c].points[k].y);
    }
  }
}

TEST(MapCleaning, EqualWeightsGiveLines) {
  auto sites = seven_sites();
  for (Site& s : sites) s.weight = 1.0;
  const Raster r = rasterize(sites, 10.0, 100, 80);
  const CleanedMap m = clean_coverage_map(polygonize(r, names(sites.size())));
  // Lines fit a staircase closely, and junctions settle where the fitted lines meet: both within
  // a third of a bin of the truth (the rings alone place junctions only to about half a bin).
  Expectations close;
  close.junction_bins = 0.35;
  close.curve_bins = 0.35;
  expect_matches(m, sites, r, rectangle(r), close);
  std::size_t lines = 0;
  for (const BoundaryChain& c : m.chains) {
    if (c.sensor_b == kNone) continue;
    EXPECT_TRUE(std::holds_alternative<Line>(c.fit.curve)) << m.sensors[c.sensor_a] << "|" << m.sensors[c.sensor_b];
    ++lines;
  }
  EXPECT_GT(lines, 8u);
  for (const auto& a : m.graph.arcs) EXPECT_TRUE(std::holds_alternative<Line>(a.curve));
}

TEST(MapCleaning, IslandIsAClosedCircle) {
  // s1 is weak and close to s0: its region is the disk of their Apollonius circle, inside s0's.
  const std::vector<Site> sites{{"s0", 300, 300, 1.0}, {"s1", 380, 330, 0.6}, {"s2", 900, 500, 1.0}};
  const Raster r = rasterize(sites, 5.0, 200, 140);
  const CleanedMap m = clean_coverage_map(polygonize(r, names(sites.size())));
  expect_matches(m, sites, r, rectangle(r));
  const int s0 = sensor_index(m, "s0"), s1 = sensor_index(m, "s1");
  const BoundaryChain* loop = nullptr;
  for (const BoundaryChain& c : m.chains)
    if (c.sensor_a == std::min(s0, s1) && c.sensor_b == std::max(s0, s1)) loop = &c;
  ASSERT_NE(loop, nullptr);
  EXPECT_EQ(loop->from, kNone);
  ASSERT_TRUE(std::holds_alternative<Circle>(loop->fit.curve));
  const auto& fit = std::get<Circle>(loop->fit.curve);
  const auto truth = std::get<Circle>(bisector(sites[0], sites[1]));
  EXPECT_NEAR(fit.cx, truth.cx, 0.02 * truth.r);
  EXPECT_NEAR(fit.cy, truth.cy, 0.02 * truth.r);
  EXPECT_NEAR(fit.r, truth.r, 0.02 * truth.r);
  // One full-circle arc; a counter-clockwise circle has its inside on the left.
  int arcs = 0;
  for (std::size_t a = 0; a < m.graph.arcs.size(); ++a) {
    if (m.chains[static_cast<std::size_t>(m.arc_chain[a])].sensor_b != loop->sensor_b ||
        m.chains[static_cast<std::size_t>(m.arc_chain[a])].sensor_a != loop->sensor_a)
      continue;
    const auto& arc = m.graph.arcs[a];
    ++arcs;
    EXPECT_EQ(arc.from, kNone);
    EXPECT_EQ(arc.to, kNone);
    const int inside = r.at({truth.cx, truth.cy});
    EXPECT_EQ(arc.ccw, arc.left_site == sensor_index(m, site_name(inside)));
  }
  EXPECT_EQ(arcs, 1);
}

TEST(MapCleaning, ConcaveFrameCorner) {
  // Coverage is an L: the north-east quarter is not covered.
  const auto sites = seven_sites();
  const Raster r = rasterize(sites, 10.0, 100, 80, [](int i, int j) { return i < 60 || j < 50; });
  const std::vector<Point> frame{{0, 0}, {1000, 0}, {1000, 500}, {600, 500}, {600, 800}, {0, 800}};
  TraceOptions o;
  o.jitter = 1.0;
  o.seed = 5;
  const CleanedMap m = clean_coverage_map(polygonize(r, names(sites.size()), o));
  expect_matches(m, sites, r, frame);
  // The frame arcs trace the L: the reflex corner is a node, and their length is its perimeter.
  double length = 0.0;
  std::vector<Point> frame_nodes;
  for (const auto& a : m.graph.arcs) {
    if (!a.frame) continue;
    const auto& p = m.graph.nodes[static_cast<std::size_t>(a.from)];
    const auto& q = m.graph.nodes[static_cast<std::size_t>(a.to)];
    length += std::hypot(q.x - p.x, q.y - p.y);
    frame_nodes.push_back({p.x, p.y});
  }
  EXPECT_NEAR(length, 3600.0, 20.0);
  EXPECT_LE(nearest(frame_nodes, {600, 500}), 2.0);
}

TEST(MapCleaning, PiecesOfOneSensorAreOneRegion) {
  // s0's region comes as two features cut along x = 250 m; its pieces touch along the cut.
  const auto sites = seven_sites();
  Raster r = rasterize(sites, 10.0, 100, 80);
  Raster pieces = r;
  const int extra = static_cast<int>(sites.size());
  for (int j = 0; j < r.ny; ++j)
    for (int i = 25; i < r.nx; ++i)
      if (pieces.at(i, j) == 0) pieces.label[static_cast<std::size_t>(j) * r.nx + i] = extra;
  auto ids = names(sites.size());
  ids.push_back("s0");
  TraceOptions o;
  o.jitter = 0.5;
  const auto cells = polygonize(pieces, ids, o);
  EXPECT_EQ(cells.size(), sites.size() + 1);
  const CleanedMap m = clean_coverage_map(cells);
  EXPECT_EQ(m.report.sensors, sites.size());
  EXPECT_GT(m.report.seams, 0u);
  expect_matches(m, sites, r, rectangle(r));
}

TEST(MapCleaning, TinyCellOnABoundaryKeepsTheGraphConsistent) {
  // One bin of a third sensor set into s0's side of the s0|s1 boundary, and one uncovered bin
  // on it: a contact too short to be a chain, and a hole in the coverage.
  const std::vector<Site> sites{{"s0", 300, 400, 1.0}, {"s1", 700, 400, 1.0}, {"s2", 500, 900, 1.0}};
  Raster r = rasterize(sites, 10.0, 100, 80);
  std::vector<std::string> ids = names(3);
  ids.push_back("tiny");
  r.label[static_cast<std::size_t>(30) * r.nx + 49] = 3;  // s0's side at x = 490..500
  const CleanedMap m = clean_coverage_map(polygonize(r, ids));
  expect_consistent(m);
  EXPECT_GT(m.report.short_chains_dropped, 0u);
  // The s0|s1 boundary is still one straight chain through the map.
  const int s0 = sensor_index(m, "s0"), s1 = sensor_index(m, "s1");
  std::size_t longest = 0;
  for (const BoundaryChain& c : m.chains)
    if (c.sensor_a == std::min(s0, s1) && c.sensor_b == std::max(s0, s1)) longest = std::max(longest, c.points.size());
  EXPECT_GT(longest, 20u);
}

TEST(MapCleaning, SlightlyRotatedGridIsStillARaster) {
  // A map re-projected about another central meridian: its grid turns by a fraction of a degree.
  const auto sites = seven_sites();
  const Raster r = rasterize(sites, 10.0, 100, 80);
  TraceOptions o;
  o.jitter = 0.5;
  const auto cells = polygonize(r, names(sites.size()), o);
  const double angle = 0.6 * kPi / 180.0, c = std::cos(angle), sn = std::sin(angle);
  const auto turn = [&](Point p) { return Point{c * p.x - sn * p.y + 5e5, sn * p.x + c * p.y + 5.2e6}; };
  auto turned = cells;
  for (auto& cell : turned)
    for (auto& polygon : cell.polygons) {
      for (auto& p : polygon.outer) p = turn(p);
      for (auto& hole : polygon.holes)
        for (auto& p : hole) p = turn(p);
    }
  std::vector<Site> turned_sites = sites;
  for (Site& s : turned_sites) {
    const Point p = turn({s.x, s.y});
    s.x = p.x, s.y = p.y;
  }
  std::vector<Point> frame;
  for (const Point& p : rectangle(r)) frame.push_back(turn(p));
  const CleanedMap straight = clean_coverage_map(cells), m = clean_coverage_map(turned);
  expect_consistent(m);
  EXPECT_NEAR(m.report.bin_size_estimate, 10.0, 0.1);
  // The same boundaries as without the turn, and junctions on the turned diagram's nodes.
  const auto pairs = [](const CleanedMap& x) {
    std::set<std::pair<int, int>> out;
    for (const BoundaryChain& ch : x.chains) out.insert({ch.sensor_a, ch.sensor_b});
    return out;
  };
  EXPECT_EQ(pairs(m), pairs(straight));
  const auto truth = true_junctions(turned_sites, frame);
  EXPECT_EQ(m.junctions.size(), truth.size());
  for (const Point& t : truth) EXPECT_LE(nearest(m.junctions, t), 2 * r.bin);
}

// Cleaning depends on the map's shape, not on where it lies: the same map moved by whole bins
// gives the same chains and junctions, moved by the same amount (to rounding).
TEST(MapCleaning, MovedMapGivesTheMovedGraph) {
  const auto sites = seven_sites();
  const Raster r = rasterize(sites, 10.0, 100, 80);
  TraceOptions o;
  o.jitter = 1.0;
  const auto cells = polygonize(r, names(sites.size()), o);
  const double dx = 5120.0, dy = -2560.0;
  auto moved_cells = cells;
  for (auto& cell : moved_cells)
    for (auto& polygon : cell.polygons) {
      for (auto& p : polygon.outer) p.x += dx, p.y += dy;
      for (auto& hole : polygon.holes)
        for (auto& p : hole) p.x += dx, p.y += dy;
    }
  const CleanedMap a = clean_coverage_map(cells), b = clean_coverage_map(moved_cells);
  ASSERT_EQ(a.chains.size(), b.chains.size());
  ASSERT_EQ(a.junctions.size(), b.junctions.size());
  const double tol = 1e-9 * (std::abs(dx) + std::abs(dy));
  for (std::size_t j = 0; j < a.junctions.size(); ++j) {
    EXPECT_NEAR(a.junctions[j].x + dx, b.junctions[j].x, tol) << "junction " << j;
    EXPECT_NEAR(a.junctions[j].y + dy, b.junctions[j].y, tol) << "junction " << j;
  }
  for (std::size_t c = 0; c < a.chains.size(); ++c) {
    EXPECT_EQ(a.chains[c].sensor_a, b.chains[c].sensor_a);
    EXPECT_EQ(a.chains[c].sensor_b, b.chains[c].sensor_b);
    ASSERT_EQ(a.chains[c].points.size(), b.chains[c].points.size()) << "chain " << c;
  }
  ASSERT_EQ(a.graph.nodes.size(), b.graph.nodes.size());
  for (std::size_t n = 0; n < a.graph.nodes.size(); ++n) {
    EXPECT_NEAR(a.graph.nodes[n].x + dx, b.graph.nodes[n].x, tol);
    EXPECT_NEAR(a.graph.nodes[n].y + dy, b.graph.nodes[n].y, tol);
  }
}

// gx × gy sites, one in each cell of a grid `spacing` wide (away from the cell's edges), weights
// uniform in [weight_min, weight_min + weight_span], and their raster of `bin` over the grid.
struct GridMap {
  std::vector<Site> sites;
  Raster raster;
};
GridMap jittered_grid(int gx, int gy, double spacing, double bin, double weight_min, double weight_span, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Site> sites;
  for (int j = 0; j < gy; ++j)
    for (int i = 0; i < gx; ++i)
      sites.push_back({site_name(static_cast<long long>(sites.size())), (i + 0.15 + 0.7 * u(rng)) * spacing,
                       (j + 0.15 + 0.7 * u(rng)) * spacing, weight_min + weight_span * u(rng)});
  Raster raster = rasterize(sites, bin, static_cast<int>(gx * spacing / bin), static_cast<int>(gy * spacing / bin));
  return {std::move(sites), std::move(raster)};
}

// Everything clean_coverage_map returns, compared exactly.
void expect_identical(const CleanedMap& got, const CleanedMap& expected, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(got.sensors, expected.sensors);
  const auto same_curve = [](const Curve& a, const Curve& b) {
    if (a.index() != b.index()) return false;
    if (const auto* c = std::get_if<Circle>(&a)) {
      const auto& d = std::get<Circle>(b);
      return c->cx == d.cx && c->cy == d.cy && c->r == d.r;
    }
    const auto& l = std::get<Line>(a);
    const auto& m = std::get<Line>(b);
    return l.x == m.x && l.y == m.y && l.dx == m.dx && l.dy == m.dy;
  };
  const auto same_points = [](const std::vector<Point>& a, const std::vector<Point>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](Point p, Point q) { return p.x == q.x && p.y == q.y; });
  };
  ASSERT_EQ(got.chains.size(), expected.chains.size());
  for (std::size_t c = 0; c < got.chains.size(); ++c) {
    const BoundaryChain &g = got.chains[c], &e = expected.chains[c];
    EXPECT_TRUE(g.sensor_a == e.sensor_a && g.sensor_b == e.sensor_b && g.from == e.from && g.to == e.to) << "chain " << c;
    EXPECT_TRUE(same_points(g.points, e.points)) << "chain " << c;
    EXPECT_TRUE(same_curve(g.fit.curve, e.fit.curve) && g.fit.rms == e.fit.rms && g.fit.max_deviation == e.fit.max_deviation)
        << "chain " << c;
  }
  EXPECT_TRUE(same_points(got.junctions, expected.junctions));
  ASSERT_EQ(got.graph.nodes.size(), expected.graph.nodes.size());
  for (std::size_t n = 0; n < got.graph.nodes.size(); ++n)
    EXPECT_TRUE(got.graph.nodes[n].x == expected.graph.nodes[n].x && got.graph.nodes[n].y == expected.graph.nodes[n].y)
        << "node " << n;
  ASSERT_EQ(got.graph.arcs.size(), expected.graph.arcs.size());
  for (std::size_t a = 0; a < got.graph.arcs.size(); ++a) {
    const Arc &g = got.graph.arcs[a], &e = expected.graph.arcs[a];
    EXPECT_TRUE(g.from == e.from && g.to == e.to && g.ccw == e.ccw && g.left_site == e.left_site &&
                g.right_site == e.right_site && g.frame == e.frame && same_curve(g.curve, e.curve))
        << "arc " << a;
  }
  EXPECT_EQ(got.arc_chain, expected.arc_chain);
  ASSERT_EQ(got.range_edges.size(), expected.range_edges.size());
  for (std::size_t r = 0; r < got.range_edges.size(); ++r) {
    EXPECT_EQ(got.range_edges[r].sensor, expected.range_edges[r].sensor);
    EXPECT_TRUE(same_curve(got.range_edges[r].fit.curve, expected.range_edges[r].fit.curve));
  }
  const CleaningReport &g = got.report, &e = expected.report;
  EXPECT_EQ(g.snap_distance, e.snap_distance);
  EXPECT_EQ(g.bin_size_estimate, e.bin_size_estimate);
  for (const auto& [name, a, b] : {std::tuple{"chains", g.chains, e.chains}, std::tuple{"junctions", g.junctions, e.junctions},
                                  std::tuple{"junctions_merged", g.junctions_merged, e.junctions_merged},
                                  std::tuple{"gaps_closed", g.gaps_closed, e.gaps_closed},
                                  std::tuple{"overlaps_resolved", g.overlaps_resolved, e.overlaps_resolved},
                                  std::tuple{"short_chains_dropped", g.short_chains_dropped, e.short_chains_dropped},
                                  std::tuple{"nodes_snapped", g.nodes_snapped, e.nodes_snapped},
                                  std::tuple{"frame_chains", g.frame_chains, e.frame_chains},
                                  std::tuple{"range_edges", g.range_edges, e.range_edges}, std::tuple{"seams", g.seams, e.seams}})
    EXPECT_EQ(a, b) << name;
}

TEST(MapCleaning, SameResultOnOneTwoThreeAndEightThreads) {
  // 600 sites with jittered, rounded copies: gaps and overlaps, and more edges (so grid entries)
  // than the 20000 below which the grid's sort stays on one thread. The reference is the serial
  // path (one thread: one batch, an unsplit sort, every ring and chain in turn); the others index,
  // sample, read, fit and refit on 2, 3 and 8 threads.
  const GridMap grid = jittered_grid(30, 20, 70.0, 5.0, 0.5, 0.5, 7);
  TraceOptions o;
  o.jitter = 0.625;
  o.round_to = 0.25;
  o.seed = 3;
  const auto cells = polygonize(grid.raster, names(grid.sites.size()), o);
  const CleanedMap reference = clean_coverage_map(cells);
  expect_consistent(reference);
  EXPECT_GT(reference.report.input_vertices, 20000u);
  EXPECT_GT(reference.report.gaps_closed, 0u);
  EXPECT_GT(reference.report.overlaps_resolved, 0u);
  for (const int threads : {1, 2, 3, 8}) {
    CleaningOptions options;
    options.threads = threads;
    expect_identical(clean_coverage_map(cells, options), reference, std::to_string(threads) + " threads");
  }
}

TEST(MapCleaning, LargeMapOfTwoThousandCells) {
  // 2000 sites with weights in [0.8, 1] on a jittered grid, ~50 bins each, jittered copies.
  const double bin = 10.0;
  const auto [sites, r] = jittered_grid(50, 40, 70.0, bin, 0.8, 0.2, 42);
  TraceOptions o;
  o.jitter = 1.0;
  const CleanedMap m = clean_coverage_map(polygonize(r, names(sites.size()), o));
  expect_consistent(m);
  EXPECT_EQ(m.report.cells, sites.size());
  // Diagram nodes closer than the merge distances become one junction; compare with tolerance.
  const auto truth = true_junctions(sites, rectangle(r));
  std::size_t found = 0, real = 0;
  for (const Point& t : truth) found += nearest(m.junctions, t) <= 2 * bin;
  for (const Point& j : m.junctions) real += nearest(truth, j) <= 2 * bin;
  EXPECT_GE(found, 0.95 * static_cast<double>(truth.size()));
  EXPECT_GE(real, 0.97 * static_cast<double>(m.junctions.size()));
  const auto touching = raster_neighbours(r);
  for (const BoundaryChain& c : m.chains) {
    if (c.sensor_b == kNone) continue;
    const int sa = std::stoi(m.sensors[static_cast<std::size_t>(c.sensor_a)].substr(1));
    const int sb = std::stoi(m.sensors[static_cast<std::size_t>(c.sensor_b)].substr(1));
    EXPECT_TRUE(touching.count({std::min(sa, sb), std::max(sa, sb)}));
  }
}

}  // namespace
}  // namespace covmap::cleaning
