// core/point_in_polygon.h against independent oracles: the winding number summed from angles for
// star-shaped polygons, the half-plane test for convex ones, and the contract's boundary rule on
// axis-parallel edges.
#include "core/point_in_polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace covmap {
namespace {

// The winding number of `ring` about p, from the angles each edge turns through.
int winding_number(const std::vector<Point>& ring, Point p) {
  double turned = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point a = ring[k], b = ring[(k + 1) % ring.size()];
    const double cross = (a.x - p.x) * (b.y - p.y) - (a.y - p.y) * (b.x - p.x);
    const double dot = (a.x - p.x) * (b.x - p.x) + (a.y - p.y) * (b.y - p.y);
    turned += std::atan2(cross, dot);
  }
  return static_cast<int>(std::lround(turned / (2 * M_PI)));
}

// The distance from p to the segment ab.
double distance_to_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

bool near_boundary(const std::vector<Point>& ring, Point p, double margin) {
  for (std::size_t k = 0; k < ring.size(); ++k)
    if (distance_to_segment(p, ring[k], ring[(k + 1) % ring.size()]) < margin) return true;
  return false;
}

// A simple polygon star-shaped about (cx, cy): n vertices at increasing angles, random radii.
std::vector<Point> star(std::mt19937_64& rng, int n, double cx, double cy) {
  std::uniform_real_distribution<double> radius(0.2, 1.0), jitter(0.0, 0.9);
  std::vector<Point> ring;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * M_PI * (k + jitter(rng)) / n;
    const double r = radius(rng);
    ring.push_back({cx + r * std::cos(angle), cy + r * std::sin(angle)});
  }
  return ring;
}

TEST(PointInPolygon, AgreesWithTheWindingNumberOffTheBoundary) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  int inside = 0, outside = 0;
  for (int polygon = 0; polygon < 200; ++polygon) {
    const auto ring = star(rng, 3 + polygon % 40, 0.1, -0.2);
    auto reversed = ring;
    std::reverse(reversed.begin(), reversed.end());
    for (int probe = 0; probe < 200; ++probe) {
      const Point p{coordinate(rng), coordinate(rng)};
      if (near_boundary(ring, p, 1e-9)) continue;
      const bool want = winding_number(ring, p) != 0;
      ASSERT_EQ(inside_ring(ring, p), want) << "polygon " << polygon << " at (" << p.x << ", " << p.y << ")";
      ASSERT_EQ(inside_ring(reversed, p), want) << "orientation changed the answer";
      (want ? inside : outside) += 1;
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
}

TEST(PointInPolygon, AgreesWithTheHalfPlanesOfAConvexPolygon) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  for (int n : {3, 4, 7, 64}) {
    std::vector<Point> ring;  // counter-clockwise on an ellipse
    for (int k = 0; k < n; ++k) ring.push_back({1.5 * std::cos(2 * M_PI * k / n), 0.75 * std::sin(2 * M_PI * k / n)});
    for (int probe = 0; probe < 5000; ++probe) {
      const Point p{coordinate(rng), coordinate(rng)};
      if (near_boundary(ring, p, 1e-9)) continue;
      bool left_of_every_edge = true;
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Point a = ring[k], b = ring[(k + 1) % ring.size()];
        left_of_every_edge = left_of_every_edge && (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) > 0;
      }
      ASSERT_EQ(inside_ring(ring, p), left_of_every_edge) << n << " vertices at (" << p.x << ", " << p.y << ")";
    }
  }
}

TEST(PointInPolygon, AxisParallelBoundaryIsHalfOpenLikeABox) {
  const std::vector<Point> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_TRUE(inside_ring(square, {0, 1}));   // left edge
  EXPECT_TRUE(inside_ring(square, {1, 0}));   // bottom edge
  EXPECT_TRUE(inside_ring(square, {0, 0}));   // lower left corner
  EXPECT_FALSE(inside_ring(square, {2, 1}));  // right edge
  EXPECT_FALSE(inside_ring(square, {1, 2}));  // top edge
  EXPECT_FALSE(inside_ring(square, {2, 0}));
  EXPECT_FALSE(inside_ring(square, {0, 2}));
  // Two cells sharing the edge x = 2 claim each of its points once.
  const std::vector<Point> right = {{2, 0}, {4, 0}, {4, 2}, {2, 2}};
  for (double y : {0.0, 0.5, 1.0, 1.999}) EXPECT_NE(inside_ring(square, {2, y}), inside_ring(right, {2, y})) << y;
}

TEST(PointInPolygon, ARepeatedClosingVertexChangesNothing) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  const auto open = star(rng, 12, 0, 0);
  auto closed = open;
  closed.push_back(open.front());
  for (int probe = 0; probe < 2000; ++probe) {
    const Point p{coordinate(rng), coordinate(rng)};
    EXPECT_EQ(inside_ring(open, p), inside_ring(closed, p));
  }
  EXPECT_FALSE(inside_ring(std::vector<Point>{}, {0, 0}));
}

TEST(PointInPolygon, HolesAndSeveralRingsAreEvenOdd) {
  CellPolygon frame;
  frame.outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  frame.holes = {{{2, 2}, {2, 4}, {4, 4}, {4, 2}}, {{6, 6}, {6, 8}, {8, 8}, {8, 6}}};
  EXPECT_TRUE(inside_polygon(frame, {1, 1}));
  EXPECT_FALSE(inside_polygon(frame, {3, 3}));
  EXPECT_FALSE(inside_polygon(frame, {7, 7}));
  EXPECT_TRUE(inside_polygon(frame, {5, 5}));
  EXPECT_FALSE(inside_polygon(frame, {11, 5}));
  std::vector<std::vector<Point>> rings = {frame.outer, frame.holes[0], frame.holes[1]};
  for (double x = -0.5; x < 11; x += 0.37)
    for (double y = -0.5; y < 11; y += 0.41) EXPECT_EQ(inside_rings(rings, {x, y}), inside_polygon(frame, {x, y}));
  // Overlapping rings: the overlap is outside, as SVG's even-odd fill draws it.
  const std::vector<std::vector<Point>> overlapping = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{2, 2}, {6, 2}, {6, 6}, {2, 6}}};
  EXPECT_TRUE(inside_rings(overlapping, {1, 1}));
  EXPECT_FALSE(inside_rings(overlapping, {3, 3}));
  EXPECT_TRUE(inside_rings(overlapping, {5, 5}));
}

}  // namespace
}  // namespace covmap
