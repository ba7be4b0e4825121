// The cleaning grid against brute force: every item within `cell` of a query point is reported,
// whatever the lengths of the segments, and a segment 10^18 cells long is added in bounded work
// (a mistyped coordinate once made one edge register in 10^9 cells and hung the audit).
#include "cleaning/neighbour_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

namespace covmap::cleaning {
namespace {

double distance_to_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

TEST(NeighbourGrid, FindsEverySegmentWithinACellAtEveryLength) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const double cell = 0.01;
    UniformGrid grid(cell);
    std::vector<std::pair<Point, Point>> segments;
    for (int i = 0; i < 200; ++i) {
      const Point a{unit(rng), unit(rng)};
      // Lengths from a tenth of a cell to 10^6 cells: every level of the grid is used.
      const double length = cell * std::pow(10.0, -1 + 7 * unit(rng));
      const double angle = 6.283185307179586 * unit(rng);
      const Point b{a.x + length * std::cos(angle), a.y + length * std::sin(angle)};
      segments.emplace_back(a, b);
      grid.add_segment(i, a, b);
    }
    grid.finish();
    for (int q = 0; q < 500; ++q) {
      const Point p{unit(rng), unit(rng)};
      std::set<int> found, half;
      grid.for_each_near(p, [&](int item) { found.insert(item); });
      grid.for_each_within_half_cell(p, [&](int item) { half.insert(item); });
      for (int i = 0; i < static_cast<int>(segments.size()); ++i) {
        const double d = distance_to_segment(p, segments[i].first, segments[i].second);
        if (d <= cell) EXPECT_TRUE(found.count(i)) << "trial " << trial << " item " << i << " at " << d;
        if (d <= cell / 2) EXPECT_TRUE(half.count(i)) << "trial " << trial << " item " << i << " at " << d;
      }
    }
  }
}

TEST(NeighbourGrid, AbsurdlyLongSegmentsCostNoMoreThanShortOnes) {
  UniformGrid grid(1e-3);
  grid.add_segment(0, {0, 0}, {0, 2147483648.0});       // a typo in a map in metres
  grid.add_segment(1, {0, 0}, {1e300, -1e300});         // longer than any level
  grid.add_segment(2, {5, 5}, {5.0005, 5});
  grid.finish();
  std::set<int> found;
  grid.for_each_near({0, 1e9}, [&](int item) { found.insert(item); });
  EXPECT_TRUE(found.count(0));
  EXPECT_TRUE(found.count(1));
  found.clear();
  grid.for_each_near({5.0002, 5.0001}, [&](int item) { found.insert(item); });
  EXPECT_TRUE(found.count(2));
}

}  // namespace
}  // namespace covmap::cleaning
