// Graphs that are not bisector graphs must be rejected with the failing element named: a node moved
// (its arcs bent to still meet there) and two faces merged (an arc removed). The graphs stay
// geometrically consistent — every arc ends on its own circle — so only the bisector conditions
// can reject them. The element named must be at the defect, which the generating data tells: the
// moved node and the other ends of its bent arcs, or the two ends of the removed arc. (The first
// failing arc in arc order can be far from the defect: a site propagated through the defect is
// wrong everywhere beyond it.)
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "recognition/recognize.h"
#include "recognition_families.h"
#include "voronoi/arc_path.h"
#include "voronoi/engine.h"

namespace covmap::recognition {
namespace {


std::vector<Site> random_sites(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(0.0, 1.0), w(1.0, 3.0);
  std::vector<Site> s;
  for (int i = 0; i < n; ++i) s.push_back({std::to_string(i), u(rng), u(rng), w(rng)});
  return s;
}

// The circle through a, m, b, travelled from a via m to b.
std::optional<std::pair<Circle, bool>> circle_through(Point a, Point m, Point b) {
  const double d = 2 * (a.x * (m.y - b.y) + m.x * (b.y - a.y) + b.x * (a.y - m.y));
  if (std::abs(d) < 1e-14) return std::nullopt;
  const double a2 = a.x * a.x + a.y * a.y, m2 = m.x * m.x + m.y * m.y, b2 = b.x * b.x + b.y * b.y;
  const double cx = (a2 * (m.y - b.y) + m2 * (b.y - a.y) + b2 * (a.y - m.y)) / d;
  const double cy = (a2 * (b.x - m.x) + m2 * (a.x - b.x) + b2 * (m.x - a.x)) / d;
  const bool ccw = (m.x - a.x) * (b.y - a.y) - (m.y - a.y) * (b.x - a.x) < 0;  // a→m→b turns left
  return std::make_pair(Circle{cx, cy, std::hypot(a.x - cx, a.y - cy)}, ccw);
}

int degree(const Diagram& d, int v) {
  int k = 0;
  for (const Arc& a : d.arcs) k += (a.from == v) + (a.to == v);
  return k;
}

Point at(const Diagram& d, int v) { return {d.nodes[v].x, d.nodes[v].y}; }
double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// A rejection whose failure names a node found by the graph's own nodes disagreeing
// (disagreeing_node.cpp), whether the start face found no candidate or every candidate failed.
bool names_disagreeing_node(const Reconstruction& r) {
  return r.failure && r.failure->node != kNone && r.reason.find("nearest the defect") != std::string::npos;
}

// The graph as generated (digits 0), or written with `digits` significant digits and recognized at
// ten units of the last digit, which the defects (1e-3 of the sites' square) are far beyond.
RecognitionOptions options_for(int digits) {
  RecognitionOptions options;
  if (digits > 0) options.relative_tolerance = std::pow(10.0, 1 - digits);
  return options;
}

void expect_shifted_node_named(int digits) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  int rejected = 0, tried = 0, located = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto sites = random_sites(rng, 15);
    Diagram d = voronoi::build_diagram(sites);
    // An inner node of degree 3 whose arcs are bounded circle arcs to other nodes.
    int v = kNone;
    for (std::size_t n = 0; n < d.nodes.size() && v == kNone; ++n) {
      if (degree(d, static_cast<int>(n)) != 3) continue;
      bool ok = true;
      for (const Arc& a : d.arcs)
        if ((a.from == static_cast<int>(n) || a.to == static_cast<int>(n)) &&
            (!std::holds_alternative<Circle>(a.curve) || a.from == kNone || a.to == kNone || a.from == a.to))
          ok = false;
      if (ok) v = static_cast<int>(n);
    }
    if (v == kNone) continue;
    const Point moved{d.nodes[v].x + 1e-3 * std::cos(angle(rng)), d.nodes[v].y + 1e-3 * std::sin(angle(rng))};
    bool bent = true;
    for (Arc& a : d.arcs) {
      if (a.from != v && a.to != v) continue;
      const voronoi::ArcPathView p = voronoi::arc_path(a, d.nodes);
      const Point mid = p.at(0.5 * (p.s0 + p.s1));
      const Point from = a.from == v ? moved : Point{d.nodes[a.from].x, d.nodes[a.from].y};
      const Point to = a.to == v ? moved : Point{d.nodes[a.to].x, d.nodes[a.to].y};
      const auto c = circle_through(from, mid, to);
      if (!c) {
        bent = false;
        break;
      }
      a.curve = c->first;
      a.ccw = c->second;
    }
    if (!bent) continue;
    d.nodes[v] = {moved.x, moved.y};
    if (digits > 0) testing::round_graph(d, digits);
    ++tried;
    const Reconstruction r = recognize(d, options_for(digits));
    EXPECT_FALSE(r.bisector_graph) << "trial " << trial;
    if (r.bisector_graph) continue;
    ASSERT_TRUE(r.failure.has_value()) << "trial " << trial;
    EXPECT_TRUE(r.failure->arc != kNone || r.failure->face != kNone || r.failure->node != kNone) << r.reason;
    EXPECT_GT(r.failure->amount, 0.0) << "trial " << trial << ": " << r.reason;
    ++rejected;
    if (!names_disagreeing_node(r)) continue;
    // The defect is the star of the moved node: it and its arcs, each bent, with their other ends.
    // The node named is one of them, and the failure's position is that node, so within the star's
    // reach (its longest arc's chord) of the moved node.
    ++located;
    double reach = 0.0;
    bool in_star = r.failure->node == v;
    for (const Arc& a : d.arcs) {
      if (a.from != v && a.to != v) continue;
      const int other = a.from == v ? a.to : a.from;
      in_star = in_star || r.failure->node == other;
      reach = std::max(reach, distance(moved, at(d, other)));
    }
    EXPECT_TRUE(in_star) << "trial " << trial << ": " << r.reason;
    EXPECT_LE(distance({r.failure->x, r.failure->y}, moved), reach * (1 + 1e-12))
        << "trial " << trial << ": " << r.reason;
    EXPECT_LE(distance({r.failure->x, r.failure->y}, at(d, r.failure->node)), 1e-12) << "trial " << trial;
  }
  EXPECT_GT(tried, 40);
  EXPECT_EQ(rejected, tried);
  ::testing::Test::RecordProperty("located", located);
  EXPECT_EQ(located, rejected) << "every rejection names the defect";
}

TEST(Negative, ShiftedNodeIsRejected) { expect_shifted_node_named(0); }
TEST(Negative, ShiftedNodeInRoundedGraphIsRejected) { expect_shifted_node_named(9); }

void expect_merged_faces_named(int digits) {
  std::mt19937_64 rng(32);
  int rejected = 0, tried = 0, located = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto sites = random_sites(rng, 15);
    Diagram d = voronoi::build_diagram(sites);
    // Remove a bounded arc between two distinct nodes of degree 3: its two faces become one.
    int victim = kNone;
    for (std::size_t a = 0; a < d.arcs.size() && victim == kNone; ++a) {
      const Arc& arc = d.arcs[a];
      if (arc.from == kNone || arc.to == kNone || arc.from == arc.to) continue;
      if (degree(d, arc.from) == 3 && degree(d, arc.to) == 3) victim = static_cast<int>(a);
    }
    if (victim == kNone) continue;
    const Arc removed = d.arcs[victim];
    d.arcs.erase(d.arcs.begin() + victim);
    clear_faces(d);
    if (digits > 0) testing::round_graph(d, digits);
    ++tried;
    const Reconstruction r = recognize(d, options_for(digits));
    EXPECT_FALSE(r.bisector_graph) << "trial " << trial;
    if (r.bisector_graph) continue;
    ASSERT_TRUE(r.failure.has_value()) << "trial " << trial;
    EXPECT_TRUE(r.failure->arc != kNone || r.failure->face != kNone || r.failure->node != kNone) << r.reason;
    ++rejected;
    if (!names_disagreeing_node(r)) continue;
    // The removed arc's two ends are left with degree two between two different curves, which no
    // bisector graph has: the node named is one of them, at its own position.
    ++located;
    EXPECT_TRUE(r.failure->node == removed.from || r.failure->node == removed.to)
        << "trial " << trial << ": " << r.reason;
    EXPECT_LE(std::min(distance({r.failure->x, r.failure->y}, at(d, removed.from)),
                       distance({r.failure->x, r.failure->y}, at(d, removed.to))),
              1e-12)
        << "trial " << trial << ": " << r.reason;
  }
  EXPECT_GT(tried, 40);
  EXPECT_EQ(rejected, tried);
  ::testing::Test::RecordProperty("located", located);
  EXPECT_EQ(located, rejected) << "every rejection names the defect";
}

TEST(Negative, MergedFacesAreRejected) { expect_merged_faces_named(0); }
TEST(Negative, MergedFacesInRoundedGraphAreRejected) { expect_merged_faces_named(9); }

}  // namespace
}  // namespace covmap::recognition

namespace covmap::recognition {
namespace {

// An arc whose stored circle misses its own end nodes (here: radius 1 % too large) is malformed;
// recognition rejects it before anything else and names that arc, one of its ends, and how far
// the end is from the circle.
TEST(Negative, ArcWhoseEndsAreOffItsCircleIsNamed) {
  std::mt19937_64 rng(41);
  int checked = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::uniform_real_distribution<double> u(0.0, 1.0), w(1.0, 2.0);
    std::vector<Site> sites;
    for (int i = 0; i < 15; ++i) sites.push_back({std::to_string(i), u(rng), u(rng), w(rng)});
    Diagram d = voronoi::build_diagram(sites);
    int changed = -1;
    double old_r = 0;
    for (std::size_t a = 0; a < d.arcs.size(); ++a)
      if (auto* c = std::get_if<Circle>(&d.arcs[a].curve); c && d.arcs[a].from != kNone && c->r < 10) {
        old_r = c->r;
        c->r *= 1.01;
        changed = static_cast<int>(a);
        break;
      }
    if (changed < 0) continue;
    const Arc arc = d.arcs[changed];
    const Reconstruction r = recognize(d);
    ASSERT_FALSE(r.bisector_graph) << "trial " << trial;
    ASSERT_TRUE(r.failure.has_value());
    EXPECT_EQ(r.failure->arc, changed) << r.reason;
    EXPECT_TRUE(r.failure->node == arc.from || r.failure->node == arc.to) << r.reason;
    EXPECT_NEAR(r.failure->amount, 0.01 * old_r, 1e-9) << r.reason;
    EXPECT_NE(r.reason.find("off the arc's curve"), std::string::npos) << r.reason;
    ++checked;
  }
  EXPECT_GT(checked, 15);
}

}  // namespace
}  // namespace covmap::recognition
