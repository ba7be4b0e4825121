// Hand-built correct diagrams must pass every check, and the checks must actually have run.
#include <gtest/gtest.h>

#include "../check/check_test_util.h"
#include "../check/hand_diagrams.h"

namespace covmap::check::testing {
namespace {

void expect_clean(const Diagram& d, std::size_t nodes) {
  const CheckReport r = check_diagram(d);
  EXPECT_TRUE(is_ok(r));
  EXPECT_EQ(r.nodes_checked, nodes);
  EXPECT_EQ(r.arc_samples_checked, d.arcs.size() * CheckOptions{}.samples_per_arc);
  EXPECT_EQ(r.boundary_points_checked, static_cast<std::size_t>(CheckOptions{}.boundary_probes));
}

TEST(CorrectDiagrams, TwoEqualSitesOneLine) { expect_clean(two_equal_sites(), 0); }
TEST(CorrectDiagrams, TwoWeightedSitesOneCircle) { expect_clean(two_weighted_sites(), 0); }
TEST(CorrectDiagrams, TriangleThreeRays) { expect_clean(triangle(), 1); }
TEST(CorrectDiagrams, SquareDegreeFourNode) { expect_clean(square(), 1); }
TEST(CorrectDiagrams, RhombusSegmentAndRays) { expect_clean(rhombus(), 2); }
TEST(CorrectDiagrams, WeightedLens) { expect_clean(weighted_lens(), 2); }
TEST(CorrectDiagrams, WeightedThetaThreeCircles) { expect_clean(weighted_theta(), 2); }
TEST(CorrectDiagrams, SmallLattice) { expect_clean(lattice(5), 16); }
// Regression: the coverage probe allowed only the tolerance, not the rounding of a huge circle's
// own numbers, and reported every correct diagram of nearly equal weights as BoundaryNotCovered.
TEST(CorrectDiagrams, NearlyEqualWeightsHugeCircle) { expect_clean(nearly_equal_weights(), 0); }

TEST(CorrectDiagrams, WeightedLensNodesMatchClosedForm) {
  // Guards the test data itself: the in-place intersection agrees with t = (-2 +- 2 sqrt 7) / 3.
  const Diagram d = weighted_lens();
  const double t1 = (-2 + 2 * std::sqrt(7.0)) / 3, t2 = (-2 - 2 * std::sqrt(7.0)) / 3;
  EXPECT_NEAR(d.nodes[0].x, t1, 1e-12);
  EXPECT_NEAR(d.nodes[0].y, t1, 1e-12);
  EXPECT_NEAR(d.nodes[1].x, t2, 1e-12);
  EXPECT_NEAR(d.nodes[1].y, t2, 1e-12);
}

TEST(CorrectDiagrams, ClippedDiagramWithFrame) {
  const Diagram d = clipped_two_sites();
  const CheckReport r = check_diagram(d);
  EXPECT_TRUE(is_ok(r));
  EXPECT_EQ(r.nodes_checked, 6u);
  EXPECT_GT(r.boundary_points_checked, 0u);
}

TEST(CorrectDiagrams, ScaleInvariant) {
  // The same diagram blown up by 1e6 and moved far away is still correct: tolerances are relative.
  Diagram d = weighted_lens();
  const double k = 1e6, ox = 3e7, oy = -2e7;
  for (Site& s : d.sites) {
    s.x = ox + k * s.x;
    s.y = oy + k * s.y;
  }
  for (Node& n : d.nodes) {
    n.x = ox + k * n.x;
    n.y = oy + k * n.y;
  }
  for (Arc& a : d.arcs) {
    if (auto* c = std::get_if<Circle>(&a.curve)) {
      *c = Circle{ox + k * c->cx, oy + k * c->cy, k * c->r};
    } else {
      auto& l = std::get<Line>(a.curve);
      l = Line{ox + k * l.x, oy + k * l.y, l.dx, l.dy};
    }
  }
  EXPECT_TRUE(is_ok(check_diagram(d)));
}

TEST(CorrectDiagrams, WithinToleranceIsAccepted) {
  // A radius off by 1e-9 of the scale is rounding, not an error (eps is 1e-7 of the scale).
  Diagram d = two_weighted_sites();
  std::get<Circle>(d.arcs[0].curve).r += 1e-9 * 3.0;
  EXPECT_TRUE(is_ok(check_diagram(d)));
}

}  // namespace
}  // namespace covmap::check::testing
