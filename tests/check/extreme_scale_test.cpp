// Diagrams at the ends of the double range. A hand-built diagram scaled by a power of two is still
// exactly the MWVD of its scaled sites (no mantissa changes), so the checker must accept it however
// large or small the factor; and a corruption must still be found, at its place in the input's units.
#include <gtest/gtest.h>

#include <cmath>

#include "../check/check_test_util.h"
#include "../check/hand_diagrams.h"

namespace covmap::check::testing {
namespace {

Diagram scaled(Diagram d, int length_exponent, int weight_exponent) {
  const auto len = [&](double v) { return std::ldexp(v, length_exponent); };
  for (Site& s : d.sites) s = {s.id, len(s.x), len(s.y), std::ldexp(s.weight, weight_exponent)};
  for (Node& n : d.nodes) n = {len(n.x), len(n.y)};
  for (Arc& a : d.arcs) {
    if (auto* c = std::get_if<Circle>(&a.curve)) *c = {len(c->cx), len(c->cy), len(c->r)};
    if (auto* l = std::get_if<Line>(&a.curve)) *l = {len(l->x), len(l->y), l->dx, l->dy};
  }
  return d;
}

struct Scales {
  int length = 0;
  int weight = 0;
};

class ExtremeScale : public ::testing::TestWithParam<Scales> {};

// Regression: weights of 1e-320 made every weighted distance infinite (ArcSidesSwapped everywhere),
// and lengths of 1e-300 or 1e300 under- or overflowed when squared.
TEST_P(ExtremeScale, CorrectDiagramsStayCorrect) {
  const Scales k = GetParam();
  for (const Diagram& d : {weighted_lens(), weighted_theta(), lattice(4), triangle()}) {
    const CheckReport r = check_diagram(scaled(d, k.length, k.weight));
    EXPECT_TRUE(is_ok(r));
    EXPECT_GT(r.boundary_points_checked, 0u);
  }
}

TEST_P(ExtremeScale, MovedNodeIsFoundWhereItIs) {
  const Scales k = GetParam();
  Diagram d = triangle();
  d.nodes[0] = Node{2.1, 1.0};
  const CheckReport r = check_diagram(scaled(d, k.length, k.weight));
  const auto v = first_of(r, ViolationKind::NodeNotEquidistant);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->node, 0);
  EXPECT_EQ(v->x, std::ldexp(2.1, k.length));
  EXPECT_EQ(v->y, std::ldexp(1.0, k.length));
  EXPECT_EQ(r.scale, std::ldexp(check_diagram(d).scale, k.length));
}

INSTANTIATE_TEST_SUITE_P(PowersOfTwo, ExtremeScale,
                         ::testing::Values(Scales{0, -1060}, Scales{0, 1000}, Scales{-1000, 0},
                                           Scales{1000, 0}, Scales{-990, -1050}, Scales{200, 0}));

}  // namespace
}  // namespace covmap::check::testing
