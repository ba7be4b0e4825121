// The sweep-line checks (io/segment_sweep.h) through their two users, io::polygon_defect and
// io::detail::find_crossing, against brute-force oracles written here: every pair of edges, with
// their own exact orientation in 128-bit integers (all coordinates are integers well below 2^50, so
// they are exact doubles and the determinants exact). The oracles share no code with the sweep or
// with core/orientation.h.
//
// Families are chosen for degeneracies: tiny integer grids (collinear edges, vertices on edges,
// repeated points), axis-parallel rings (vertical edges, overlaps along a line), stars, combs,
// spirals, fans of edges through one point (a proper crossing hidden among touching edges, the case
// the sweep's proof is about), and simple polygons with one injected defect (a vertex moved onto
// another vertex, onto another edge, or just past it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "io/coverage_map_crossings.h"
#include "io/polygon_check.h"
#include "io/segment_sweep.h"

namespace covmap::io {
namespace {

using Ring = std::vector<Point>;
using Rings = std::vector<Ring>;

// ---- the oracles ----

std::int64_t integer(double v) { return static_cast<std::int64_t>(v); }

int orient(Point a, Point b, Point c) {
  const __int128 det = static_cast<__int128>(integer(b.x) - integer(a.x)) * (integer(c.y) - integer(a.y)) -
                       static_cast<__int128>(integer(b.y) - integer(a.y)) * (integer(c.x) - integer(a.x));
  return (det > 0) - (det < 0);
}

bool equal(Point p, Point q) { return p.x == q.x && p.y == q.y; }

// p lies on the closed segment a-b.
bool on_segment(Point a, Point b, Point p) {
  return orient(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

bool proper_cross(Point a, Point b, Point c, Point d) {
  return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
}

// The closed segments share a point.
bool closed_meet(Point a, Point b, Point c, Point d) {
  return proper_cross(a, b, c, d) || on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) ||
         on_segment(c, d, b);
}

// The documented checks of polygon_defect, in its order; the first that fails.
enum class Defect { kTooFew, kRepeat, kZeroArea, kOverlap, kNotSimple, kNone };

Defect oracle_defect(const Ring& r) {
  const std::size_t n = r.size();
  if (n < 3) return Defect::kTooFew;
  for (std::size_t i = 0; i < n; ++i) {
    if (equal(r[i], r[(i + 1) % n])) return Defect::kRepeat;
  }
  bool line = true;
  for (std::size_t i = 2; i < n; ++i) line = line && orient(r[0], r[1], r[i]) == 0;
  if (line) return Defect::kZeroArea;
  // Consecutive edges u-s, s-w overlap when u and w lie on one ray from s.
  for (std::size_t i = 0; i < n; ++i) {
    const Point u = r[i], s = r[(i + 1) % n], w = r[(i + 2) % n];
    const double dot = (u.x - s.x) * (w.x - s.x) + (u.y - s.y) * (w.y - s.y);
    if (orient(u, s, w) == 0 && dot > 0) return Defect::kOverlap;
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (closed_meet(r[i], r[(i + 1) % n], r[j], r[(j + 1) % n])) return Defect::kNotSimple;
    }
  }
  return Defect::kNone;
}

bool oracle_crossing(const Rings& rings) {
  std::vector<std::pair<Point, Point>> edges;
  for (const Ring& r : rings) {
    for (std::size_t i = 0; i < r.size(); ++i) edges.emplace_back(r[i], r[(i + 1) % r.size()]);
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      if (proper_cross(edges[i].first, edges[i].second, edges[j].first, edges[j].second)) return true;
    }
  }
  return false;
}

// Some two edges meet other than consecutive edges of one ring at their shared vertex.
bool oracle_touching(const Rings& rings) {
  struct Edge {
    std::size_t ring, index;
    Point a, b;
  };
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (std::size_t i = 0; i < rings[r].size(); ++i) edges.push_back({r, i, rings[r][i], rings[r][(i + 1) % rings[r].size()]});
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge &e = edges[i], &f = edges[j];
      const std::size_t n = rings[e.ring].size();
      if (e.ring == f.ring && (f.index == e.index + 1 || (e.index == 0 && f.index == n - 1))) continue;
      if (closed_meet(e.a, e.b, f.a, f.b)) return true;
    }
  }
  return false;
}

// ---- checking one answer against the oracle ----

struct Tally {
  int cases = 0;
  int with_defect = 0;   // or with a crossing
  int touching_only = 0;  // not simple, but no proper crossing: what only a touching-aware test sees
};

// polygon_defect(ring) is right: the same kind of defect as the oracle's first, and a named pair of
// edges (or pair of vertices) that really meets.
void check_polygon(const Ring& r, const std::string& family, Tally& tally) {
  ++tally.cases;
  const Defect want = oracle_defect(r);
  const auto got = polygon_defect(r);
  ASSERT_EQ(got.has_value(), want != Defect::kNone) << family << ": " << got.value_or("simple");
  if (!got) return;
  ++tally.with_defect;
  const std::string& m = *got;
  switch (want) {
    case Defect::kTooFew: EXPECT_NE(m.find("at least 3"), std::string::npos) << m; return;
    case Defect::kRepeat: EXPECT_NE(m.find("repeats the vertex before it"), std::string::npos) << m; return;
    case Defect::kZeroArea: EXPECT_NE(m.find("zero area"), std::string::npos) << m; return;
    case Defect::kOverlap: EXPECT_NE(m.find("and the next edge overlap"), std::string::npos) << m; return;
    case Defect::kNotSimple: break;
    case Defect::kNone: return;
  }
  if (!oracle_crossing({r})) ++tally.touching_only;
  static const std::regex edges(R"(^the polygon is not simple: edge (\d+) \([^)]*\) -> \d+ \([^)]*\) meets edge (\d+) \()");
  static const std::regex vertices(R"(^the polygon is not simple: vertex (\d+) \([^)]*\) and vertex (\d+) \([^)]*\) are the same point$)");
  std::smatch match;
  const std::size_t n = r.size();
  if (std::regex_search(m, match, edges)) {
    const std::size_t i = std::stoul(match[1]), j = std::stoul(match[2]);
    ASSERT_LT(i, j) << m;
    ASSERT_LT(j, n) << m;
    EXPECT_FALSE(j == i + 1 || (i == 0 && j == n - 1)) << "consecutive edges named: " << m;
    EXPECT_TRUE(closed_meet(r[i], r[(i + 1) % n], r[j], r[(j + 1) % n])) << "these edges do not meet: " << m;
  } else if (std::regex_search(m, match, vertices)) {
    const std::size_t i = std::stoul(match[1]), j = std::stoul(match[2]);
    ASSERT_LT(i, j) << m;
    ASSERT_LT(j, n) << m;
    EXPECT_TRUE(equal(r[i], r[j])) << m;
  } else {
    ADD_FAILURE() << "unexpected message: " << m;
  }
}

// find_crossing(rings) is right: a crossing exactly when the oracle has one, and the named pair
// really crosses properly.
void check_rings(const Rings& rings, const std::string& family, Tally& tally) {
  ++tally.cases;
  const bool want = oracle_crossing(rings);
  const auto got = detail::find_crossing(rings);
  ASSERT_EQ(got.has_value(), want) << family;
  if (!got) {
    tally.touching_only += oracle_touching(rings);
    return;
  }
  ++tally.with_defect;
  const auto [first, second] = *got;
  ASSERT_LT(first, second) << family;
  ASSERT_LT(second.ring, rings.size());
  const Ring& ra = rings[first.ring];
  const Ring& rb = rings[second.ring];
  ASSERT_LT(first.edge, ra.size());
  ASSERT_LT(second.edge, rb.size());
  EXPECT_TRUE(proper_cross(ra[first.edge], ra[(first.edge + 1) % ra.size()], rb[second.edge],
                           rb[(second.edge + 1) % rb.size()]))
      << family << ": the named edges do not cross";
  const auto again = detail::find_crossing(rings);  // deterministic
  ASSERT_TRUE(again);
  EXPECT_EQ(again->first, first);
  EXPECT_EQ(again->second, second);
}

// ---- families (integer coordinates) ----

using Random = std::mt19937;

int uniform(Random& random, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); }

// n points on a (side+1)^2 grid, consecutive points distinct unless `repeats`.
Ring grid_ring(Random& random, int n, int side, bool repeats = false) {
  Ring r;
  while (static_cast<int>(r.size()) < n) {
    const Point p{static_cast<double>(uniform(random, 0, side)), static_cast<double>(uniform(random, 0, side))};
    if (!repeats && !r.empty() && equal(r.back(), p)) continue;
    r.push_back(p);
  }
  return r;
}

// Grid points sorted by angle about a centre (exact order: half plane, then cross product):
// star-shaped, simple unless points share a ray or the centre lies on the boundary.
Ring star_ring(Random& random, int n, int side) {
  Ring r = grid_ring(random, n, side);
  const Point c{static_cast<double>(uniform(random, 0, side)), static_cast<double>(uniform(random, 0, side))};
  const auto upper = [&](Point p) { return p.y > c.y || (p.y == c.y && p.x > c.x); };
  std::sort(r.begin(), r.end(), [&](Point p, Point q) {
    if (upper(p) != upper(q)) return upper(p);
    return orient(c, p, q) > 0;
  });
  r.erase(std::unique(r.begin(), r.end(), equal), r.end());
  return r;
}

// An axis-parallel x-monotone polygon: bars of random heights over [0, 2 * bars], on the floor y = 0.
Ring histogram_ring(Random& random, int bars, int height, int x0 = 0, int y0 = 0) {
  Ring r;
  r.push_back({static_cast<double>(x0), static_cast<double>(y0)});
  int previous = -1;
  for (int b = 0; b < bars; ++b) {
    int h = uniform(random, 1, height);
    if (h == previous) h = h == height ? h - 1 : h + 1;  // no collinear vertex on the roof
    if (h < 1) h = 2;
    r.push_back({static_cast<double>(x0 + 2 * b), static_cast<double>(y0 + h)});
    r.push_back({static_cast<double>(x0 + 2 * b + 2), static_cast<double>(y0 + h)});
    previous = h;
  }
  r.push_back({static_cast<double>(x0 + 2 * bars), static_cast<double>(y0)});
  return r;
}

// A comb: `teeth` teeth of random height and width 1..2, gaps 1..2, on a base bar.
Ring comb_ring(Random& random, int teeth, int height) {
  Ring r;
  int x = 0;
  r.push_back({0, -1});
  for (int t = 0; t < teeth; ++t) {
    const int width = uniform(random, 1, 2), h = uniform(random, 1, height);
    r.push_back({static_cast<double>(x), 0});
    r.push_back({static_cast<double>(x), static_cast<double>(h)});
    r.push_back({static_cast<double>(x + width), static_cast<double>(h)});
    r.push_back({static_cast<double>(x + width), 0});
    x += width + uniform(random, 1, 2);
  }
  r.push_back({static_cast<double>(x), 0});
  r.push_back({static_cast<double>(x), -1});
  // Drop vertices in the middle of a straight run (the first and last tooth meet the base there).
  Ring out;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[(i + r.size() - 1) % r.size()], b = r[i], c = r[(i + 1) % r.size()];
    if (orient(a, b, c) != 0) out.push_back(b);
  }
  return out;
}

// A thick spiral strip (inner and outer spiral joined at both ends) rounded to integers: simple
// when `scale` is large against the rounding, touching or crossing itself when it is small.
Ring spiral_ring(std::size_t per_boundary, double turns, double scale) {
  const std::size_t m = per_boundary;
  const double total = 2 * std::numbers::pi * turns;
  Ring r(2 * m);
  for (std::size_t k = 0; k < m; ++k) {
    const double t = total * static_cast<double>(k) / static_cast<double>(m - 1);
    const double inner = scale * (1 + t / (2 * std::numbers::pi)), outer = inner + scale / 2;
    r[k] = {std::round(inner * std::cos(t)), std::round(inner * std::sin(t))};
    r[2 * m - 1 - k] = {std::round(outer * std::cos(t)), std::round(outer * std::sin(t))};
  }
  return r;
}

// A convex polygon: lattice points near a circle, in angle order (rounding may make some of them
// collinear or repeated, which the oracle decides).
Ring circle_ring(Random& random, int n, int radius) {
  Ring r;
  const double phase = uniform(random, 0, 1000) / 1000.0;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * (k + phase) / n;
    const Point p{std::round(radius * std::cos(t)), std::round(radius * std::sin(t))};
    if (r.empty() || !equal(r.back(), p)) r.push_back(p);
  }
  while (r.size() > 1 && equal(r.back(), r.front())) r.pop_back();
  return r;
}

// A lattice point strictly inside edge a-b, if it has one.
std::optional<Point> inner_lattice_point(Random& random, Point a, Point b) {
  const auto dx = integer(b.x) - integer(a.x), dy = integer(b.y) - integer(a.y);
  const auto g = std::gcd(std::abs(dx), std::abs(dy));
  if (g < 2) return std::nullopt;
  const auto t = std::uniform_int_distribution<std::int64_t>(1, g - 1)(random);
  return Point{a.x + static_cast<double>(t * (dx / g)), a.y + static_cast<double>(t * (dy / g))};
}

// One defect injected into a ring: a vertex moved onto another vertex, onto a lattice point inside
// a non-adjacent edge (touching), one unit past such a point, or anywhere nearby.
Ring inject(Random& random, Ring r) {
  const int n = static_cast<int>(r.size());
  if (n < 5) return r;
  const int v = uniform(random, 0, n - 1);
  int e = uniform(random, 0, n - 1);  // an edge not touching vertex v
  for (int tries = 0; tries < 20 && (e == v || (e + 1) % n == v); ++tries) e = uniform(random, 0, n - 1);
  if (e == v || (e + 1) % n == v) return r;
  const Point a = r[e], b = r[(e + 1) % n];
  switch (uniform(random, 0, 3)) {
    case 0: r[v] = a; break;  // a repeated vertex
    case 1:
      if (const auto p = inner_lattice_point(random, a, b)) r[v] = *p;  // touching
      break;
    case 2:
      if (const auto p = inner_lattice_point(random, a, b)) {  // just past the edge
        r[v] = {p->x + uniform(random, -1, 1), p->y + uniform(random, -1, 1)};
      }
      break;
    default: r[v] = {r[v].x + uniform(random, -3, 3), r[v].y + uniform(random, -3, 3)}; break;
  }
  Ring out;  // keep "no two consecutive vertices equal" most of the time, as readers ensure
  for (const Point& p : r) {
    if (out.empty() || !equal(out.back(), p)) out.push_back(p);
  }
  while (out.size() > 1 && equal(out.back(), out.front())) out.pop_back();
  return out;
}

// A vertex moved onto a lattice point inside a non-adjacent edge, when one is found: a touch,
// which may or may not also make edges cross.
Ring touch(Random& random, Ring r) {
  const int n = static_cast<int>(r.size());
  for (int tries = 0; tries < 50 && n >= 5; ++tries) {
    const int v = uniform(random, 0, n - 1), e = uniform(random, 0, n - 1);
    if (e == v || (e + 1) % n == v || (e + n - 1) % n == v || (e + 2) % n == v) continue;
    if (const auto p = inner_lattice_point(random, r[e], r[(e + 1) % n])) {
      r[v] = *p;
      return r;
    }
  }
  return r;
}

// ---- polygon_defect ----

TEST(PolygonDefectSweep, AgreesWithBruteForceOnDegenerateFamilies) {
  Random random(20261);
  Tally tally;
  for (int trial = 0; trial < 1500; ++trial) {  // tiny grids: mostly defects of every kind
    const int side = std::array{2, 3, 4, 6, 12, 400}[trial % 6];
    check_polygon(grid_ring(random, uniform(random, 3, 24), side, trial % 10 == 0), "grid", tally);
  }
  for (int trial = 0; trial < 800; ++trial) {
    const Ring r = star_ring(random, uniform(random, 3, 40), std::array{3, 5, 8, 30}[trial % 4]);
    check_polygon(trial % 3 == 0 ? inject(random, r) : r, "star", tally);
  }
  for (int trial = 0; trial < 600; ++trial) {
    const Ring r = histogram_ring(random, uniform(random, 1, 12), uniform(random, 1, 6));
    check_polygon(trial % 2 == 0 ? inject(random, r) : r, "histogram", tally);
  }
  for (int trial = 0; trial < 600; ++trial) {
    const Ring r = comb_ring(random, uniform(random, 1, 10), uniform(random, 1, 5));
    check_polygon(trial % 2 == 0 ? inject(random, r) : r, "comb", tally);
  }
  for (int trial = 0; trial < 400; ++trial) {
    const Ring r = spiral_ring(static_cast<std::size_t>(uniform(random, 8, 120)), uniform(random, 1, 40) / 10.0,
                               std::array{1.0, 2.0, 5.0, 40.0, 1000.0}[trial % 5]);
    check_polygon(trial % 3 == 0 ? inject(random, r) : r, "spiral", tally);
  }
  for (int trial = 0; trial < 600; ++trial) {
    const Ring r = circle_ring(random, uniform(random, 3, 60), std::array{2, 5, 20, 1000}[trial % 4]);
    check_polygon(trial % 2 == 0 ? inject(random, r) : r, "circle", tally);
  }
  for (int trial = 0; trial < 1000; ++trial) {  // simple polygons with one vertex moved onto an edge
    Ring r;
    switch (trial % 4) {
      case 0: r = histogram_ring(random, uniform(random, 2, 10), uniform(random, 2, 8)); break;
      case 1: r = comb_ring(random, uniform(random, 2, 8), uniform(random, 2, 6)); break;
      case 2: r = circle_ring(random, uniform(random, 5, 40), std::array{4, 30, 1000}[trial % 3]); break;
      default: r = star_ring(random, uniform(random, 5, 30), 10); break;
    }
    check_polygon(touch(random, r), "touch", tally);
  }
  // Both answers and the touching-only defects (invisible to a proper-crossing test) are well
  // represented.
  EXPECT_EQ(tally.cases, 5500);
  EXPECT_GT(tally.with_defect, 1500);
  EXPECT_GT(tally.cases - tally.with_defect, 1000);
  EXPECT_GT(tally.touching_only, 300);
  std::printf("polygon_defect: %d polygons, %d with a defect, %d of them touching without crossing\n", tally.cases,
              tally.with_defect, tally.touching_only);
}

TEST(PolygonDefectSweep, NamesEachKindOfMeeting) {
  // A vertex on the interior of a vertical edge, of a horizontal edge, and a repeated vertex.
  EXPECT_EQ(polygon_defect(Ring{{0, 0}, {4, 0}, {4, 4}, {2, 4}, {2, 2}, {4, 2}, {3, 1}}).value(),
            "the polygon is not simple: edge 1 (4, 0) -> 2 (4, 4) meets edge 5 (4, 2) -> 6 (3, 1)");
  EXPECT_EQ(polygon_defect(Ring{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}).value(), 
            "the polygon is not simple: edge 0 (0, 0) -> 1 (4, 0) meets edge 3 (2, 0) -> 4 (0, 4)");
  EXPECT_EQ(polygon_defect(Ring{{0, 0}, {4, 0}, {2, 2}, {4, 4}, {0, 4}, {2, 2}}).value(),
            "the polygon is not simple: vertex 2 (2, 2) and vertex 5 (2, 2) are the same point");
  // Non-adjacent edges overlapping along a horizontal line, and the same turned to vertical.
  const Ring horizontal{{0, 0}, {4, 0}, {4, 1}, {2, 1}, {2, 0}, {1, 0}, {0, 3}};
  Ring vertical;
  for (const Point p : horizontal) vertical.push_back({p.y, p.x});
  for (const Ring& r : {horizontal, vertical}) {
    ASSERT_EQ(oracle_defect(r), Defect::kNotSimple);
    EXPECT_NE(polygon_defect(r).value_or("").find("not simple"), std::string::npos);
  }
  // Vertical edges in a row, sharing only their consecutive vertex: simple.
  EXPECT_FALSE(polygon_defect(Ring{{0, 0}, {1, 0}, {1, 1}, {1.5, 2}, {1, 3}, {1, 4}, {0, 4}}));
}

// ---- find_crossing ----

// Rings through one point c: edges ending at c, starting at c and passing through it, from lattice
// directions, so that a proper crossing at c sits among edges that only touch there.
Rings fan_rings(Random& random, int side) {
  const Point c{static_cast<double>(uniform(random, -side, side)), static_cast<double>(uniform(random, -side, side))};
  const auto direction = [&] {
    Point d{0, 0};
    while (d.x == 0 && d.y == 0) d = {static_cast<double>(uniform(random, -2, 2)), static_cast<double>(uniform(random, -2, 2))};
    return d;
  };
  Rings rings;
  const int count = uniform(random, 1, 4);
  for (int k = 0; k < count; ++k) {
    const Point d = direction(), e = direction();
    const double s = uniform(random, 1, 3), t = uniform(random, 1, 3);
    switch (uniform(random, 0, 2)) {
      case 0:  // a triangle with a vertex at c: two edges end or start there
        rings.push_back({c, {c.x + s * d.x, c.y + s * d.y}, {c.x + t * e.x, c.y + t * e.y}});
        break;
      case 1:  // a triangle with an edge through c
        rings.push_back({{c.x - s * d.x, c.y - s * d.y}, {c.x + t * d.x, c.y + t * d.y}, {c.x + t * e.x, c.y + t * e.y}});
        break;
      default:  // a quadrilateral whose diagonal-free sides pass near c
        rings.push_back({{c.x - s * d.x, c.y - s * d.y}, {c.x + s * d.x, c.y + s * d.y}, {c.x + t * e.x, c.y + t * e.y},
                         {c.x - t * e.x, c.y - t * e.y}});
        break;
    }
  }
  for (Ring& r : rings) r.erase(std::unique(r.begin(), r.end(), equal), r.end());
  std::erase_if(rings, [](const Ring& r) { return r.size() < 3; });
  if (rings.empty()) rings.push_back({{0, 0}, {1, 0}, {0, 1}});
  return rings;
}

TEST(FindCrossingSweep, AgreesWithBruteForceOnDegenerateFamilies) {
  Random random(77);
  Tally tally;
  for (int trial = 0; trial < 1500; ++trial) {  // one to three rings on tiny grids, some with repeats
    const int side = std::array{2, 3, 4, 8, 400}[trial % 5];
    Rings rings(static_cast<std::size_t>(uniform(random, 1, 3)));
    for (Ring& r : rings) r = grid_ring(random, uniform(random, 3, 16), side, trial % 7 == 0);
    check_rings(rings, "grid", tally);
  }
  for (int trial = 0; trial < 1000; ++trial) check_rings(fan_rings(random, 3), "fan", tally);
  for (int trial = 0; trial < 600; ++trial) {  // axis-parallel rings overlapping one another
    Rings rings(static_cast<std::size_t>(uniform(random, 1, 4)));
    for (Ring& r : rings) r = histogram_ring(random, uniform(random, 1, 6), uniform(random, 1, 5), uniform(random, -4, 4), uniform(random, -3, 3));
    if (trial % 3 == 0) rings[0] = inject(random, rings[0]);
    check_rings(rings, "histograms", tally);
  }
  for (int trial = 0; trial < 500; ++trial) {
    Rings rings{star_ring(random, uniform(random, 3, 30), std::array{4, 6, 20}[trial % 3])};
    if (trial % 2 == 0) rings.push_back(star_ring(random, uniform(random, 3, 12), 6));
    if (trial % 3 == 0) rings[0] = inject(random, rings[0]);
    check_rings(rings, "stars", tally);
  }
  for (int trial = 0; trial < 400; ++trial) {
    Rings rings{comb_ring(random, uniform(random, 1, 10), uniform(random, 1, 5))};
    if (trial % 2 == 0) rings[0] = inject(random, rings[0]);
    if (trial % 4 == 1) rings.push_back({{-1, 1}, {500, 1}, {500, 2}});  // a long edge across the teeth
    check_rings(rings, "comb", tally);
  }
  for (int trial = 0; trial < 300; ++trial) {
    Rings rings{spiral_ring(static_cast<std::size_t>(uniform(random, 8, 100)), uniform(random, 1, 40) / 10.0,
                            std::array{1.0, 3.0, 40.0}[trial % 3])};
    if (trial % 2 == 0) rings[0] = inject(random, rings[0]);
    check_rings(rings, "spiral", tally);
  }
  EXPECT_EQ(tally.cases, 4300);
  EXPECT_GT(tally.with_defect, 1000);
  EXPECT_GT(tally.cases - tally.with_defect, 1000);
  EXPECT_GT(tally.touching_only, 300);  // rings that touch themselves without crossing: no crossing
  std::printf("find_crossing: %d ring sets, %d with a crossing, %d touching without crossing\n", tally.cases,
              tally.with_defect, tally.touching_only);
}

TEST(FindCrossingSweep, CrossingHiddenAmongTouchingEdges) {
  // Everything meets at the origin: segments ending there from the left and from below, starting
  // there to the right and upwards, lying along the two crossing segments, and the two segments
  // that cross properly there. The sweep must find that crossing whatever the order of the input.
  std::vector<detail::Segment> segments{
      {{-3, -3}, {3, 3}},  {{-3, 3}, {3, -3}},                                          // the crossing
      {{-2, -1}, {0, 0}},  {{-1, 0}, {0, 0}},  {{-2, 1}, {0, 0}},  {{0, -2}, {0, 0}},  // ending there
      {{0, 0}, {2, 1}},    {{0, 0}, {0, 2}},   {{0, 0}, {1, 3}},                        // starting there
      {{-1, -1}, {0, 0}},  {{0, 0}, {2, -2}},  {{2, 2}, {0, 0}},                        // along them
  };
  Random random(3);
  const auto cross = [&](std::size_t i, std::size_t j) {
    return detail::properly_cross(segments[i].a, segments[i].b, segments[j].a, segments[j].b);
  };
  for (int trial = 0; trial < 2000; ++trial) {
    std::shuffle(segments.begin(), segments.end(), random);
    if (trial % 2) {
      for (auto& s : segments) std::swap(s.a, s.b);
    }
    const auto found = detail::find_adjacent_pair(segments, cross);
    ASSERT_TRUE(found) << "trial " << trial;
    EXPECT_TRUE(proper_cross(segments[found->first].a, segments[found->first].b, segments[found->second].a,
                             segments[found->second].b));
  }
  // Without one of the crossing pair, only touches and overlaps remain.
  std::erase_if(segments, [](const detail::Segment& s) { return (s.a.x == -3 && s.a.y == 3) || (s.b.x == -3 && s.b.y == 3); });
  ASSERT_EQ(segments.size(), 11u);
  EXPECT_FALSE(detail::find_adjacent_pair(segments, cross));
}

TEST(FindCrossingSweep, CollinearOverlapsAndZeroLengthEdgesAreNotCrossings) {
  // Two squares sharing a side, a triangle along that side (with a repeated vertex: an edge of
  // length zero), and one along part of the bottom.
  const Rings touching{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2, 0}, {4, 0}, {4, 2}, {2, 2}},
                       {{2, 0}, {2, 2}, {2, 2}, {3, 1}}, {{0, 0}, {1, 0}, {1, 1}}};
  EXPECT_FALSE(detail::find_crossing(touching));
  EXPECT_FALSE(oracle_crossing(touching));
  // The same with the third ring nudged across the shared side.
  const Rings crossing{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 1}, {3, 1}, {3, 3}}};
  const auto got = detail::find_crossing(crossing);
  ASSERT_TRUE(got);
  EXPECT_EQ(got->first, (detail::EdgeRef{0, 1}));
  EXPECT_EQ(got->second, (detail::EdgeRef{1, 0}));
}

// ---- the sweep itself ----

TEST(SegmentSweep, TestsFewPairsAndIgnoresZeroLength) {
  // A fine circle: nothing accepted, and the test called at most 3 times per segment.
  std::vector<detail::Segment> segments;
  const int n = 5000;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n, b = 2 * std::numbers::pi * (k + 1) / n;
    segments.push_back({{std::cos(a), std::sin(a)}, {std::cos(b), std::sin(b)}});
  }
  segments.push_back({{0, 0}, {0, 0}});
  std::size_t calls = 0;
  const auto none = detail::find_adjacent_pair(segments, [&](std::size_t i, std::size_t j) {
    ++calls;
    EXPECT_LT(i, j);
    EXPECT_NE(j, segments.size() - 1) << "the zero-length segment was tested";
    return false;
  });
  EXPECT_FALSE(none);
  EXPECT_LE(calls, 3 * segments.size());
  EXPECT_GE(calls, segments.size() / 2);
}

// ---- large polygons ----

// The double-precision spiral of the benchmark (not integers: the sweep's orientation signs are
// exact for any doubles).
Ring fine_spiral(std::size_t n) {
  const std::size_t m = n / 2;
  const double turns = std::max(2.0, std::round(std::sqrt(static_cast<double>(n)) / 8));
  const double total = 2 * std::numbers::pi * turns;
  Ring r(2 * m);
  for (std::size_t k = 0; k < m; ++k) {
    const double t = total * static_cast<double>(k) / static_cast<double>(m - 1);
    const double inner = 1 + t / (2 * std::numbers::pi);
    r[k] = {inner * std::cos(t), inner * std::sin(t)};
    r[2 * m - 1 - k] = {(inner + 0.5) * std::cos(t), (inner + 0.5) * std::sin(t)};
  }
  return r;
}

TEST(PolygonChecksLarge, FineSpiralIsSimple) {
  // 2 * 10^5 vertices, ~56 turns: a few hundred edges on the sweep line at once. (The benchmark
  // runs the same shape at 10^6: docs/PERFORMANCE.md.)
  const Ring r = fine_spiral(200000);
  EXPECT_FALSE(polygon_defect(r)) << polygon_defect(r).value_or("");
  EXPECT_FALSE(detail::find_crossing(Rings{r}));
}

TEST(PolygonChecksLarge, TouchAndCrossingInALargeIntegerSpiral) {
  // 10^5 vertices on integers; a spike from one turn of the inner spiral reaches exactly onto an
  // edge of the previous turn's outer spiral (a touch), or a little past it (a crossing).
  const std::size_t m = 50000;
  const double turns = 40;
  const Ring r = spiral_ring(m, turns, 10000);
  ASSERT_FALSE(polygon_defect(r)) << polygon_defect(r).value_or("");
  ASSERT_FALSE(detail::find_crossing(Rings{r}));

  Random random(5);
  const auto per_turn = static_cast<std::size_t>(static_cast<double>(m - 1) / turns);
  std::size_t target = 0;  // an outer edge with a lattice point inside, half way out
  std::optional<Point> touch;
  for (std::size_t k = m / 2; !touch; ++k) {
    target = 2 * m - 1 - k;  // the outer vertex at the angle of inner vertex k
    touch = inner_lattice_point(random, r[target], r[target - 1]);
  }
  const std::size_t spike_after = (2 * m - 1 - target) + per_turn;  // the inner vertex one turn further out
  const auto with_spike = [&](Point tip) {
    Ring s(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(spike_after) + 1);
    s.push_back(tip);
    s.insert(s.end(), r.begin() + static_cast<std::ptrdiff_t>(spike_after) + 1, r.end());
    return s;
  };
  const Ring touching = with_spike(*touch);
  const auto defect = polygon_defect(touching);
  ASSERT_TRUE(defect);
  EXPECT_NE(defect->find("not simple"), std::string::npos) << *defect;
  EXPECT_FALSE(detail::find_crossing(Rings{touching}));

  // About two units towards the centre: just past the edge, inside the 5 000-unit-wide strip behind it.
  const double norm = std::hypot(touch->x, touch->y);
  const Point past{touch->x - std::round(2 * touch->x / norm), touch->y - std::round(2 * touch->y / norm)};
  const auto crossing = detail::find_crossing(Rings{with_spike(past)});
  ASSERT_TRUE(crossing);
  EXPECT_TRUE(polygon_defect(with_spike(past)));
}

}  // namespace
}  // namespace covmap::io
