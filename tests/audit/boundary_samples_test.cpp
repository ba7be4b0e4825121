// audit::sample_boundaries on cleaned maps whose chains are built here with known geometry
// (straight, bent and circular polylines, frame chains, short and degenerate chains) and on one map
// cleaned from two rectangles: every sample lies on its chain (and within the chord error of the
// chain's fitted curve), consecutive samples are `spacing` apart along the chain (or length /
// max_per_chain when that is longer), starting half a step in, and carry the chain's sensors,
// the chain index and the stated sigma. Frame chains (no second sensor) give no samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "audit/boundary_samples.h"

namespace covmap::audit {
namespace {

constexpr double kPi = 3.14159265358979323846;

cleaning::BoundaryChain chain(int a, int b, std::vector<Point> points, Curve curve = Line{}) {
  cleaning::BoundaryChain c;
  c.sensor_a = a, c.sensor_b = b;
  c.points = std::move(points);
  c.fit.curve = curve;
  return c;
}

cleaning::CleanedMap map_of(std::vector<cleaning::BoundaryChain> chains, int sensors) {
  cleaning::CleanedMap m;
  for (int s = 0; s < sensors; ++s) m.sensors.push_back("s" + std::to_string(s));
  m.chains = std::move(chains);
  return m;
}

// Arc-length position of p along a polyline and its distance from it (the nearest segment).
struct OnPolyline {
  double s = 0.0, distance = std::numeric_limits<double>::infinity();
};
OnPolyline locate(const std::vector<Point>& pts, Point p) {
  OnPolyline best;
  double walked = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const double dx = pts[k + 1].x - pts[k].x, dy = pts[k + 1].y - pts[k].y, len = std::hypot(dx, dy);
    const double t = std::clamp(((p.x - pts[k].x) * dx + (p.y - pts[k].y) * dy) / (len * len), 0.0, 1.0);
    const double d = std::hypot(pts[k].x + t * dx - p.x, pts[k].y + t * dy - p.y);
    if (d < best.distance) best = {walked + t * len, d};
    walked += len;
  }
  return best;
}

double length(const std::vector<Point>& pts) {
  double l = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) l += std::hypot(pts[k + 1].x - pts[k].x, pts[k + 1].y - pts[k].y);
  return l;
}

double distance_to_curve(const Curve& c, Point p) {
  if (const auto* circle = std::get_if<Circle>(&c)) return std::abs(std::hypot(p.x - circle->cx, p.y - circle->cy) - circle->r);
  const Line& l = std::get<Line>(c);
  return std::abs((p.x - l.x) * l.dy - (p.y - l.y) * l.dx) / std::hypot(l.dx, l.dy);
}

TEST(BoundarySamples, StraightChainEverySpacingFromHalfASpacingIn) {
  // Along y = 2x + 1 from x = 0 to x = 4: length 4√5 ≈ 8.944; spacing 1: samples at arc length
  // 0.5, 1.5, …, 8.5 (9 of them), each on the line.
  const Point a{0, 1}, b{4, 9};
  const double L = std::hypot(4.0, 8.0);
  const auto m = map_of({chain(1, 2, {a, b}, Line{0, 1, 1, 2})}, 3);
  const auto s = sample_boundaries(m, 1.0, 0.25);
  ASSERT_EQ(s.size(), 9u);
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double at = 0.5 + static_cast<double>(k);
    EXPECT_NEAR(s[k].p.x, a.x + at / L * (b.x - a.x), 1e-12) << k;
    EXPECT_NEAR(s[k].p.y, a.y + at / L * (b.y - a.y), 1e-12) << k;
    EXPECT_NEAR(distance_to_curve(m.chains[0].fit.curve, s[k].p), 0.0, 1e-12);
    EXPECT_EQ(s[k].site_a, 1);
    EXPECT_EQ(s[k].site_b, 2);
    EXPECT_EQ(s[k].chain, 0);
    EXPECT_EQ(s[k].sigma, 0.25);
  }
}

TEST(BoundarySamples, BentChainIsWalkedAlongItsLength) {
  // (0,0) → (3,0) → (3,4): length 7; spacing 1 gives arc lengths 0.5 … 6.5, the corner after 3.
  const std::vector<Point> pts{{0, 0}, {3, 0}, {3, 4}};
  const auto s = sample_boundaries(map_of({chain(0, 1, pts)}, 2), 1.0, 1.0);
  const std::vector<Point> expect{{0.5, 0}, {1.5, 0}, {2.5, 0}, {3, 0.5}, {3, 1.5}, {3, 2.5}, {3, 3.5}};
  ASSERT_EQ(s.size(), expect.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    EXPECT_NEAR(s[k].p.x, expect[k].x, 1e-12) << k;
    EXPECT_NEAR(s[k].p.y, expect[k].y, 1e-12) << k;
  }
}

TEST(BoundarySamples, CircularChainSamplesLieOnTheFittedCircleWithinTheChordError) {
  // 40 vertices on a quarter of the circle of radius 50 about (7, -3): the samples lie on the
  // chords, at most the sagitta R (1 − cos(Δθ/2)) from the circle; in arc length along the
  // polyline they are `spacing` apart.
  const double R = 50.0, cx = 7.0, cy = -3.0;
  const int n = 40;
  const double dtheta = 0.5 * kPi / (n - 1);
  std::vector<Point> pts;
  for (int k = 0; k < n; ++k) pts.push_back({cx + R * std::cos(k * dtheta), cy + R * std::sin(k * dtheta)});
  const auto m = map_of({chain(0, 1, pts, Circle{cx, cy, R})}, 2);
  const double sagitta = R * (1.0 - std::cos(0.5 * dtheta));
  const double spacing = 2.0;
  const double L = length(pts);
  const auto s = sample_boundaries(m, spacing, 0.5, 1000);
  ASSERT_EQ(s.size(), static_cast<std::size_t>(std::floor(L / spacing + 0.5)));
  for (std::size_t k = 0; k < s.size(); ++k) {
    const OnPolyline at = locate(pts, s[k].p);
    EXPECT_LT(at.distance, 1e-9) << k;
    EXPECT_NEAR(at.s, spacing * (0.5 + static_cast<double>(k)), 1e-9) << k;
    EXPECT_LE(distance_to_curve(m.chains[0].fit.curve, s[k].p), sagitta * (1 + 1e-9)) << k;
  }
  // The sagitta bound is tight enough to mean something: 0.25 m·(Δθ)² scale, far below a spacing.
  EXPECT_LT(sagitta, 0.01 * spacing);
}

TEST(BoundarySamples, LongChainIsCappedAtMaxPerChainEvenlySpread) {
  // Length 100, spacing 1, at most 32: step 100/32 = 3.125, samples at 1.5625 + 3.125 k.
  const auto m = map_of({chain(0, 1, {{0, 0}, {100, 0}})}, 2);
  const auto capped = sample_boundaries(m, 1.0, 1.0, 32);
  ASSERT_EQ(capped.size(), 32u);
  for (std::size_t k = 0; k < capped.size(); ++k) EXPECT_NEAR(capped[k].p.x, 1.5625 + 3.125 * k, 1e-12) << k;
  // The default cap is 32 too.
  EXPECT_EQ(sample_boundaries(m, 1.0, 1.0).size(), 32u);
  // No cap (max_per_chain 0): one per spacing.
  EXPECT_EQ(sample_boundaries(m, 1.0, 1.0, 0).size(), 100u);
  // A spacing coarser than length / cap wins over the cap.
  EXPECT_EQ(sample_boundaries(m, 10.0, 1.0, 32).size(), 10u);
}

TEST(BoundarySamples, FrameChainsGiveNoSamplesAndIndicesFollowTheChains) {
  // Chain 0 a frame chain (sensor 0 against the outside), chain 1 between 0 and 2, chain 2 a frame
  // chain of sensor 2, chain 3 between 1 and 2.
  const auto m = map_of({chain(0, kNone, {{0, 0}, {0, 10}}), chain(0, 2, {{5, 0}, {5, 4}}),
                         chain(2, kNone, {{10, 0}, {10, 10}}), chain(1, 2, {{5, 4}, {9, 4}})},
                        3);
  const auto s = sample_boundaries(m, 1.0, 0.1);
  ASSERT_EQ(s.size(), 8u);
  for (const auto& x : s) {
    ASSERT_TRUE(x.chain == 1 || x.chain == 3) << x.chain;
    EXPECT_EQ(x.site_a, m.chains[x.chain].sensor_a);
    EXPECT_EQ(x.site_b, m.chains[x.chain].sensor_b);
    EXPECT_LT(locate(m.chains[x.chain].points, x.p).distance, 1e-12);
  }
}

TEST(BoundarySamples, ShortAndDegenerateChains) {
  // Shorter than half a spacing: one sample, the chain's middle point. A single point: itself.
  // No points: nothing.
  const auto m = map_of({chain(0, 1, {{0, 0}, {0.1, 0}, {0.2, 0}}), chain(1, 2, {{3, 3}}), chain(0, 2, {})}, 3);
  const auto s = sample_boundaries(m, 1.0, 0.5);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].chain, 0);
  EXPECT_DOUBLE_EQ(s[0].p.x, 0.1);
  EXPECT_EQ(s[1].chain, 1);
  EXPECT_DOUBLE_EQ(s[1].p.x, 3.0);
  EXPECT_DOUBLE_EQ(s[1].p.y, 3.0);
}

TEST(BoundarySamples, OnAMapCleanedFromTwoRectangles) {
  // A | B along x = 10, for 0 < y < 10: every sample of the shared chain is on that line, between
  // the sensors A (0) and B (1) in order of first appearance.
  std::vector<CoverageCell> cells(2);
  cells[0].sensor = "A";
  cells[0].polygons = {{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}}};
  cells[1].sensor = "B";
  cells[1].feature = 1;
  cells[1].polygons = {{{{10, 0}, {20, 0}, {20, 10}, {10, 10}}, {}}};
  cleaning::CleaningOptions options;
  options.snap_distance = 0.5;
  const cleaning::CleanedMap m = cleaning::clean_coverage_map(cells, options);
  ASSERT_EQ(m.sensors, (std::vector<std::string>{"A", "B"}));
  const auto s = sample_boundaries(m, 1.0, 0.3);
  ASSERT_GE(s.size(), 5u);
  for (const auto& x : s) {
    EXPECT_EQ(x.site_a, 0);
    EXPECT_EQ(x.site_b, 1);
    EXPECT_NEAR(x.p.x, 10.0, 1e-9);
    EXPECT_GT(x.p.y, 0.0);
    EXPECT_LT(x.p.y, 10.0);
    EXPECT_LT(distance_to_curve(m.chains[x.chain].fit.curve, x.p), 1e-9);
    EXPECT_EQ(x.sigma, 0.3);
  }
}

}  // namespace
}  // namespace covmap::audit
