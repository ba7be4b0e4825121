// Lemma 5 against its closed form: around a node of three weighted bisectors, the inversions in
// bisector(s, t), then bisector(t, u), then bisector(u, s) carry s to t to u and back to s, so s is
// on the fixed set of the composition. Both readings (exact, least squares) must find a circle
// through s, and the same circle.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mobius/node_constraint.h"
#include "voronoi/engine.h"

namespace covmap::mobius {
namespace {

int arc_between(const Diagram& d, int v, int a, int b) {
  for (std::size_t k = 0; k < d.arcs.size(); ++k) {
    const Arc& arc = d.arcs[k];
    if (arc.from != v && arc.to != v) continue;
    if ((arc.left_site == a && arc.right_site == b) || (arc.left_site == b && arc.right_site == a))
      return static_cast<int>(k);
  }
  return kNone;
}

TEST(NodeConstraint, BothReadingsFindTheCircleThroughTheSite) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> pos(-10.0, 10.0), weight(0.5, 2.0);
  int checked = 0;
  for (int trial = 0; trial < 200 && checked < 60; ++trial) {
    const std::vector<Site> sites = {{"s", pos(rng), pos(rng), weight(rng)},
                                     {"t", pos(rng), pos(rng), weight(rng)},
                                     {"u", pos(rng), pos(rng), weight(rng)}};
    const Diagram d = voronoi::build_diagram(sites);
    for (std::size_t v = 0; v < d.nodes.size(); ++v) {
      const int st = arc_between(d, static_cast<int>(v), 0, 1), tu = arc_between(d, static_cast<int>(v), 1, 2),
                us = arc_between(d, static_cast<int>(v), 2, 0);
      if (st == kNone || tu == kNone || us == kNone) continue;
      const Complex node(d.nodes[v].x, d.nodes[v].y);
      const Complex far = node + Complex(pos(rng), pos(rng));
      const NodeFrame frame{node, std::abs(far - node)};
      Mobius m;
      for (int a : {st, tu, us}) m = then_invert_in(m, d.arcs[a], frame);
      ASSERT_TRUE(m.conjugated());  // three inversions: anti-Möbius
      const NodeConstraint exact = exact_fixed_set(m, 1e-9);
      ASSERT_TRUE(exact.is_circle) << "trial " << trial;
      const GeneralizedCircle by_exact = frame.to_plane(exact.circle);
      const GeneralizedCircle by_least_squares = frame.to_plane(least_squares_fixed_circle(m));
      const Complex s(sites[0].x, sites[0].y);
      const double size = std::abs(s - node) + frame.unit;
      EXPECT_LT(distance_to(by_exact, s), 1e-9 * size) << "trial " << trial;
      EXPECT_LT(distance_to(by_least_squares, s), 1e-9 * size) << "trial " << trial;
      // The solution circle passes through the node too (the origin of the frame is fixed).
      EXPECT_LT(distance_to(by_exact, node), 1e-9 * size) << "trial " << trial;
      ++checked;
    }
  }
  EXPECT_GE(checked, 30);
}

TEST(NodeConstraint, AnEvenRoundTripOfOneReflectionIsTheIdentity) {
  // Crossing the same line twice: the identity, no constraint (exact), no second fixed point.
  Arc line;
  line.curve = Line{0.0, 0.0, 1.0, 2.0};
  line.from = 0;
  const NodeFrame frame{Complex(0.0, 0.0), 1.0};
  Mobius m;
  m = then_invert_in(m, line, frame);
  m = then_invert_in(m, line, frame);
  EXPECT_TRUE(exact_fixed_set(m, 1e-12).any);
  EXPECT_FALSE(other_fixed_point(m, 1e-9).has_value());
}

}  // namespace
}  // namespace covmap::mobius
