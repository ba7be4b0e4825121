// Arc sampling and face rings for the audit reports, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "report/audit_geometry.h"
#include "audit_test_fixture.h"

namespace covmap::report {
namespace {


// One circle arc of radius 100 around the origin from angle 0 to 100 degrees, counter-clockwise.
Diagram quarter_arc(double radius) {
  Diagram d;
  const double end = 100.0 * std::numbers::pi / 180.0;
  d.nodes = {{radius, 0.0}, {radius * std::cos(end), radius * std::sin(end)}};
  d.arcs = {{0, 1, Circle{0, 0, radius}, true, 0, 1, false}};
  return d;
}

TEST(AuditArcSampling, CircleArcPointsOnTheCircleWithBoundedStepAndSagitta) {
  for (const double radius : {0.001, 1.0, 100.0, 1e6}) {
    SCOPED_TRACE(radius);
    const Diagram d = quarter_arc(radius);
    detail::ArcSampling s;
    s.max_step_radians = 2.0 * std::numbers::pi / 180.0;
    s.max_deviation = 0.01;
    s.max_line_step = std::numeric_limits<double>::infinity();
    const auto points = detail::sample_half_arc(d, {0, true}, s);
    ASSERT_GE(points.size(), 51u);  // 100 degrees in steps of at most 2
    EXPECT_EQ(points.front().x, d.nodes[0].x);
    EXPECT_EQ(points.front().y, d.nodes[0].y);
    EXPECT_EQ(points.back().x, d.nodes[1].x);
    EXPECT_EQ(points.back().y, d.nodes[1].y);
    double previous = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      EXPECT_NEAR(std::hypot(points[i].x, points[i].y), radius, 1e-12 * radius);
      const double angle = std::atan2(points[i].y, points[i].x);
      if (i > 0) {
        const double step = angle - previous;
        EXPECT_GT(step, 0.0);  // counter-clockwise
        EXPECT_LE(step, s.max_step_radians + 1e-12);
        EXPECT_LE(radius * (1 - std::cos(step / 2)), s.max_deviation * (1 + 1e-9));  // sagitta
      }
      previous = angle;
    }
    // Backwards: the same points reversed.
    const auto back = detail::sample_half_arc(d, {0, false}, s);
    ASSERT_EQ(back.size(), points.size());
    EXPECT_EQ(back.front().x, points.back().x);
    EXPECT_EQ(back.back().y, points.front().y);
  }
}

TEST(AuditArcSampling, LinesAreOneSegmentUnlessAStepIsGiven) {
  Diagram d;
  d.nodes = {{0, 0}, {10, 0}};
  d.arcs = {{0, 1, Line{0, 0, 1, 0}, true, 0, 1, false},
            {kNone, 1, Line{0, 0, 1, 0}, true, 0, 1, false}};
  detail::ArcSampling s{0.1, 0.1, std::numeric_limits<double>::infinity()};
  EXPECT_EQ(detail::sample_half_arc(d, {0, true}, s).size(), 2u);
  s.max_line_step = 3.0;
  const auto cut = detail::sample_half_arc(d, {0, true}, s);
  ASSERT_EQ(cut.size(), 5u);  // ceil(10 / 3) = 4 pieces
  EXPECT_DOUBLE_EQ(cut[1].x, 2.5);
  EXPECT_TRUE(detail::sample_half_arc(d, {1, true}, s).empty());  // a ray cannot be sampled
}

TEST(AuditRegions, FullCircleFaceIsARoundRingOfTheRightArea) {
  // Two sites with weights 1 and 2 four apart: 'a''s region is the disk of radius 8/3 around
  // (-4/3, 0) (Apollonius circle of ratio 1/2), so its area is pi (8/3)^2.
  Diagram d = voronoi::build_diagram(std::vector<Site>{{"a", 0, 0, 1}, {"b", 4, 0, 2}});
  const auto s = detail::arc_sampling(AuditRenderOptions{}, detail::diagram_extent(d), false);
  const auto regions = detail::diagram_regions(d, s);
  ASSERT_EQ(regions.regions.size(), 1u);  // b's face is unbounded
  EXPECT_EQ(regions.unbounded_faces, 1u);
  const auto& a = regions.regions.front();
  EXPECT_EQ(d.sites[a.site].id, "a");
  ASSERT_EQ(a.polygons.size(), 1u);
  const double r = 8.0 / 3.0;
  EXPECT_NEAR(a.area, std::numbers::pi * r * r, 1e-4 * r * r);
  EXPECT_GT(detail::signed_area(a.polygons[0].outer), 0.0);
  EXPECT_GE(a.polygons[0].outer.size(), 360u);
  for (const Point& p : a.polygons[0].outer) EXPECT_NEAR(std::hypot(p.x + 4.0 / 3.0, p.y), r, 1e-9);
}

TEST(AuditRegions, SignedAreaOfASquare) {
  const Ring square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(detail::signed_area(square), 4.0);
  EXPECT_DOUBLE_EQ(detail::signed_area(Ring(square.rbegin(), square.rend())), -4.0);
}

TEST(AuditGeography, ContinuousLongitudeAcrossTheAntimeridian) {
  const io::LocalProjection p = io::LocalProjection::about(179.9, -17.0);  // Fiji
  const Point east = p.forward(-179.95, -17.0);  // across the antimeridian, 0.15 degrees east
  const io::LonLat plain = detail::to_lonlat(p, east);
  const io::LonLat continuous = detail::to_lonlat_continuous(p, east);
  EXPECT_NEAR(plain.lon, -179.95, 1e-9);
  EXPECT_NEAR(continuous.lon, 180.05, 1e-9);
  EXPECT_NEAR(continuous.lat, -17.0, 1e-9);
}

}  // namespace
}  // namespace covmap::report
