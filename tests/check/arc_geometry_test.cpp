// Constructions of the checker's arc geometry against closed forms.
#include "check/arc_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../check/hand_diagrams.h"

namespace covmap::check::detail {
namespace {

using testing::circle_arc;
using testing::line_arc;

TEST(ArcGeometry, HugeCircleMeetsSmallCircleOnBoth) {
  // Radius ~7e4 against ~0.3 (docs/NUMERICS.md, 'Circle–circle intersection'). Both intersection
  // points must be on both circles.
  const std::vector<Node> none;
  const ArcPath big =
      make_arc_path(circle_arc(kNone, kNone, Circle{70000.1, 0.2, 70000}, true, 0, 1), none);
  const ArcPath small =
      make_arc_path(circle_arc(kNone, kNone, Circle{0.05, 0.1, 0.3}, true, 0, 1), none);
  const CurveIntersection hit = intersect_curves(big, small, 1e-12, 1.0);
  ASSERT_EQ(hit.points.size(), 2u);
  for (const Point& p : hit.points) {
    EXPECT_NEAR(std::hypot(p.x - 0.05, p.y - 0.1), 0.3, 1e-13);
    // |p - c| - R, evaluated in long double to see past the cancellation.
    const long double dx = p.x - 70000.1L, dy = p.y - 0.2L;
    EXPECT_LT(std::abs(std::sqrt(dx * dx + dy * dy) - 70000.0L), 1e-10L);
  }
}

TEST(ArcGeometry, LineLineAndCircleLine) {
  const std::vector<Node> none;
  const ArcPath x1 = make_arc_path(line_arc(kNone, kNone, Line{1, 0, 0, 1}, 0, 1), none);
  const ArcPath diag = make_arc_path(line_arc(kNone, kNone, Line{0, 0, 1, 1}, 0, 1), none);
  CurveIntersection hit = intersect_curves(x1, diag, 1e-12, 1.0);
  ASSERT_EQ(hit.points.size(), 1u);
  EXPECT_NEAR(hit.points[0].x, 1.0, 1e-15);
  EXPECT_NEAR(hit.points[0].y, 1.0, 1e-15);
  const ArcPath unit =
      make_arc_path(circle_arc(kNone, kNone, Circle{0, 0, std::sqrt(2.0)}, true, 0, 1), none);
  hit = intersect_curves(unit, diag, 1e-12, 1.0);
  ASSERT_EQ(hit.points.size(), 2u);
  for (const Point& p : hit.points) EXPECT_NEAR(std::abs(p.x) + std::abs(p.y), 2.0, 1e-14);
  EXPECT_TRUE(intersect_curves(x1, x1, 1e-12, 1.0).coincident);
}

TEST(ArcGeometry, CircleArcParametersAndBox) {
  // The quarter from (1,0) to (0,1) counter-clockwise, and the three quarters clockwise.
  const std::vector<Node> nodes = {Node{1, 0}, Node{0, 1}};
  const ArcPath ccw = make_arc_path(circle_arc(0, 1, Circle{0, 0, 1}, true, 0, 1), nodes);
  EXPECT_NEAR(ccw.s1, M_PI / 2, 1e-15);
  const ArcPath cw = make_arc_path(circle_arc(0, 1, Circle{0, 0, 1}, false, 0, 1), nodes);
  EXPECT_NEAR(cw.s1, 3 * M_PI / 2, 1e-15);
  const Box b = bounding_box(cw, Box{});
  EXPECT_DOUBLE_EQ(b.xmin, -1);
  EXPECT_DOUBLE_EQ(b.ymin, -1);
  EXPECT_DOUBLE_EQ(b.xmax, 1);
  EXPECT_DOUBLE_EQ(b.ymax, 1);
  EXPECT_TRUE(is_interior_point(cw, {0, -1}, 1e-9));
  EXPECT_FALSE(is_interior_point(ccw, {0, -1}, 1e-9));
  EXPECT_FALSE(is_interior_point(ccw, {1, 0}, 1e-9));                   // an end node
  EXPECT_NEAR(distance_to_arc(ccw, {0, -2}), std::hypot(1, 2), 1e-15);  // nearest end: (1,0)
}

TEST(ArcGeometry, ClipCircleToBox) {
  // The unit circle against the box [0, 2] x [-2, 2]: the right half, from -90 to 90 degrees.
  const ArcPath full = make_arc_path(circle_arc(kNone, kNone, Circle{0, 0, 1}, true, 0, 1), {});
  const auto pieces = clip_to_box(full, Box{0, -2, 2, 2});
  double total = 0;
  for (const auto& [a, b] : pieces) {
    total += b - a;
    EXPECT_GE(full.at(0.5 * (a + b)).x, 0.0);
  }
  EXPECT_NEAR(total, M_PI, 1e-12);
}

TEST(ArcGeometry, ClipHugeCircleToSmallBox) {
  // A circle of radius 1e7 through the origin: inside the unit box its arc is about 2 long.
  const ArcPath huge =
      make_arc_path(circle_arc(kNone, kNone, Circle{0, -1e7, 1e7}, true, 0, 1), {});
  const auto pieces = clip_to_box(huge, Box{-1, -1, 1, 1});
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR((pieces[0].second - pieces[0].first) * huge.radius, 2.0, 1e-6);
}

}  // namespace
}  // namespace covmap::check::detail
