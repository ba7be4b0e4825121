// One reading of a circle arc's extent (core/arc_sweep.h) for the diagram's geometry
// (voronoi/arc_path.h) and the independent checker (check/arc_geometry.h): closed forms for
// quarter arcs, loops and full circles; two distinct nodes at the same angle bound an arc of length
// zero in both (the path read it as a full circle and the checker as zero length, and comparing
// graphs then reported a full circle that was not there); and both readers agree bit for bit on
// random arcs.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "check/arc_geometry.h"
#include "core/arc_sweep.h"
#include "voronoi/arc_path.h"

namespace covmap {
namespace {

constexpr double kPi = 3.14159265358979323846;

Arc circle_arc(int from, int to, Circle c, bool ccw) {
  Arc a;
  a.from = from;
  a.to = to;
  a.curve = c;
  a.ccw = ccw;
  return a;
}

// Both readers' (start angle, sweep) of one arc, which must be the same.
std::pair<double, double> read_both(const Arc& arc, const std::vector<Node>& nodes) {
  const voronoi::ArcPathView v = voronoi::arc_path(arc, nodes);
  const check::detail::ArcPath c = check::detail::make_arc_path(arc, nodes);
  EXPECT_EQ(v.start_angle, c.start_angle);
  EXPECT_EQ(v.s0, c.s0);
  EXPECT_EQ(v.s1, c.s1);
  return {v.start_angle, v.s1};
}

TEST(ArcExtent, QuarterArcsLoopsAndFullCircles) {
  const Circle unit{0, 0, 1};
  const std::vector<Node> nodes = {{1, 0}, {0, 1}};
  EXPECT_NEAR(read_both(circle_arc(0, 1, unit, true), nodes).second, kPi / 2, 1e-15);
  EXPECT_NEAR(read_both(circle_arc(0, 1, unit, false), nodes).second, 3 * kPi / 2, 1e-15);
  // A loop from a node once round: the full circle, from the node's angle.
  const auto loop = read_both(circle_arc(1, 1, unit, true), nodes);
  EXPECT_EQ(loop.second, kTwoPi);
  EXPECT_NEAR(loop.first, kPi / 2, 1e-15);
  // No nodes: the full circle from angle 0.
  const auto full = read_both(circle_arc(kNone, kNone, unit, false), nodes);
  EXPECT_EQ(full.first, 0.0);
  EXPECT_EQ(full.second, kTwoPi);
  EXPECT_TRUE(circle_arc_sweep(circle_arc(1, 1, unit, true), unit, nodes).full);
}

TEST(ArcExtent, DistinctNodesAtTheSameAngleBoundAnArcOfLengthZero) {
  const Circle c{0.25, -0.5, 3.0};
  // The same point twice, and two points on one ray from the centre (off the circle by rounding).
  const std::vector<Node> nodes = {{3.25, -0.5}, {3.25, -0.5}, {0.25 + 3.0 * std::cos(1.0), -0.5 + 3.0 * std::sin(1.0)},
                                   {0.25 + (3.0 + 1e-12) * std::cos(1.0), -0.5 + (3.0 + 1e-12) * std::sin(1.0)}};
  for (bool ccw : {true, false}) {
    EXPECT_EQ(read_both(circle_arc(0, 1, c, ccw), nodes).second, 0.0);
    // On one ray the two atan2 may differ in the last bit: whatever the sweep, both read it alike.
    EXPECT_FALSE(circle_arc_sweep(circle_arc(2, 3, c, ccw), c, nodes).full);
    read_both(circle_arc(2, 3, c, ccw), nodes);
  }
  // An angle a hair below zero rounds to 2π when 2π is added: it is zero, not a full turn.
  EXPECT_EQ(wrap_angle(-1e-300), 0.0);
  EXPECT_EQ(wrap_angle(-kTwoPi), 0.0);
  EXPECT_LT(wrap_angle(kTwoPi), kTwoPi);
}

TEST(ArcExtent, BothReadersAgreeOnRandomArcs) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(-kPi, kPi), radius(1e-3, 1e4);
  for (int trial = 0; trial < 2000; ++trial) {
    const Circle c{u(rng) * 100, u(rng) * 100, radius(rng)};
    const double a = angle(rng), b = trial % 7 == 0 ? a : angle(rng);
    const std::vector<Node> nodes = {{c.cx + c.r * std::cos(a), c.cy + c.r * std::sin(a)},
                                     {c.cx + c.r * std::cos(b), c.cy + c.r * std::sin(b)}};
    const Arc arc = circle_arc(0, trial % 11 == 0 ? 0 : 1, c, trial % 2 == 0);
    const double sweep = read_both(arc, nodes).second;
    EXPECT_GE(sweep, 0.0);
    EXPECT_LE(sweep, kTwoPi);
  }
}

}  // namespace
}  // namespace covmap
