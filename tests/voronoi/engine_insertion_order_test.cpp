// The diagram of spatial inputs (lifted sites spanning space) must not depend on the order in
// which the sites enter the regular triangulation: the triangulation is the same complex in every
// order, but CGAL stores its cells, and each cell's vertices, in an order that follows the
// insertion (and would follow the thread schedule of a parallel insertion). The spatial extractor
// reads the triangulation through canonical numbers (engine/flat_triangulation.h), so every order
// must give the same file: the same nodes to the bit, the same arcs in the same order with the
// same sites on each side, the same faces. Three unrelated orders are compared: CGAL's spatial
// sort of (x, y, w), the sort of (x, y) that build_diagram uses, and the input order.
#include <gtest/gtest.h>

#include <variant>
#include <vector>

#include "site_families.h"
#include "voronoi/engine/build_in_order.h"

namespace covmap::voronoi::engine {
namespace {

using testing::Family;

bool same_curve(const Curve& a, const Curve& b) {
  if (a.index() != b.index()) return false;
  if (const Circle* c = std::get_if<Circle>(&a)) {
    const Circle& d = std::get<Circle>(b);
    return c->cx == d.cx && c->cy == d.cy && c->r == d.r;
  }
  const Line& l = std::get<Line>(a);
  const Line& m = std::get<Line>(b);
  return l.x == m.x && l.y == m.y && l.dx == m.dx && l.dy == m.dy;
}

void expect_identical(const Diagram& want, const Diagram& got, const char* what) {
  ASSERT_EQ(got.nodes.size(), want.nodes.size()) << what;
  ASSERT_EQ(got.arcs.size(), want.arcs.size()) << what;
  ASSERT_EQ(got.faces.size(), want.faces.size()) << what;
  for (std::size_t k = 0; k < want.nodes.size(); ++k) {
    ASSERT_EQ(got.nodes[k].x, want.nodes[k].x) << what << ", node " << k;
    ASSERT_EQ(got.nodes[k].y, want.nodes[k].y) << what << ", node " << k;
  }
  for (std::size_t k = 0; k < want.arcs.size(); ++k) {
    const Arc& a = want.arcs[k];
    const Arc& b = got.arcs[k];
    ASSERT_TRUE(a.from == b.from && a.to == b.to && a.ccw == b.ccw && a.left_site == b.left_site &&
                a.right_site == b.right_site && a.frame == b.frame && same_curve(a.curve, b.curve))
        << what << ", arc " << k;
  }
  for (std::size_t k = 0; k < want.faces.size(); ++k) {
    const Face& f = want.faces[k];
    const Face& g = got.faces[k];
    ASSERT_TRUE(f.site == g.site && f.bounded == g.bounded && f.orphan == g.orphan &&
                f.cycles_begin == g.cycles_begin && f.cycles_end == g.cycles_end)
        << what << ", face " << k;
  }
  ASSERT_EQ(got.cycles.size(), want.cycles.size()) << what;
  for (std::size_t k = 0; k < want.cycles.size(); ++k)
    ASSERT_TRUE(got.cycles[k].begin == want.cycles[k].begin && got.cycles[k].end == want.cycles[k].end) << what;
  ASSERT_EQ(got.half_arcs.size(), want.half_arcs.size()) << what;
  for (std::size_t k = 0; k < want.half_arcs.size(); ++k)
    ASSERT_TRUE(got.half_arcs[k].arc == want.half_arcs[k].arc && got.half_arcs[k].forward == want.half_arcs[k].forward)
        << what << ", half-arc " << k;
}

class EngineInsertionOrderTest : public ::testing::TestWithParam<Family> {};

TEST_P(EngineInsertionOrderTest, EveryInsertionOrderGivesTheSameDiagram) {
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    const auto sites = testing::make_sites(GetParam(), 3000, seed);
    BuildStats stats;
    const Diagram reference = build_diagram_in_order(sites, InsertionOrder::kSpatial3, &stats);
    ASSERT_EQ(stats.triangulation_dimension, 3) << "a spatial family";
    expect_identical(reference, build_diagram_in_order(sites, InsertionOrder::kHilbert2), "(x, y) order");
    expect_identical(reference, build_diagram_in_order(sites, InsertionOrder::kAsGiven), "input order");
    expect_identical(reference, build_diagram(sites), "build_diagram");
  }
}

// The families whose lifted sites span space (equal weights and collinear sites do not: their
// triangulation is planar or linear, always inserted in one order).
INSTANTIATE_TEST_SUITE_P(Families, EngineInsertionOrderTest,
                         ::testing::Values(Family::UniformWeights, Family::WeightClasses, Family::SharedMaximum,
                                           Family::Grid, Family::LargeCoordinates),
                         [](const auto& info) { return testing::family_name(info.param); });

}  // namespace
}  // namespace covmap::voronoi::engine
