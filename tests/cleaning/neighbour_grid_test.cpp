// The cleaning grid against brute force: every item within `cell` of a query point is reported,
// whatever the lengths of the segments, and a segment 10^18 cells long is added in bounded work
// (a mistyped coordinate once made one edge register in 10^9 cells and hung the audit).
#include "cleaning/neighbour_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "core/parallel.h"

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
        if (d <= cell) {
          EXPECT_TRUE(found.count(i)) << "trial " << trial << " item " << i << " at " << d;
        }
        if (d <= cell / 2) {
          EXPECT_TRUE(half.count(i)) << "trial " << trial << " item " << i << " at " << d;
        }
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

// Map boundaries: many short edges covering a region densely, as a coverage map's are, and a few
// long ones (coarse levels). The dense
// table must then serve every query with exactly the hash's items in the hash's order (the audit's
// results depend on the order of ties), and find everything within reach (brute force). Regions on
// both sides of the origin and below it, and one across 2^27 cells, where rows wrap around the key
// space (the table leaves those to the hash).
TEST(NeighbourGrid, DenseTableVisitsWhatTheHashVisitsInTheSameOrder) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cell = 1.0;
  for (const Point origin : {Point{0, 0}, Point{-40, -40}, Point{-20, 7}, Point{-80.5, -3.25}, Point{134217708, 5}}) {
    UniformGrid dense(cell), hashed(cell, UniformGrid::Index::kHashOnly);
    std::vector<std::pair<Point, Point>> segments;
    for (int i = 0; i < 4000; ++i) {
      const Point a{origin.x + 40 * unit(rng), origin.y + 40 * unit(rng)};
      // One in forty is long (up to 10^4 cells, as a map's outer border): the coarse levels too.
      const double length = cell * (i % 40 == 0 ? std::pow(10.0, 4 * unit(rng)) : 2 * unit(rng));
      const double angle = 6.283185307179586 * unit(rng);
      segments.emplace_back(a, Point{a.x + length * std::cos(angle), a.y + length * std::sin(angle)});
      dense.add_segment(i, segments.back().first, segments.back().second);
      hashed.add_segment(i, segments.back().first, segments.back().second);
    }
    dense.finish();
    hashed.finish();
    for (int q = 0; q < 2000; ++q) {
      const Point p{origin.x - 2 + 44 * unit(rng), origin.y - 2 + 44 * unit(rng)};
      std::vector<int> near_dense, near_hashed, half_dense, half_hashed;
      dense.for_each_near(p, [&](int item) { near_dense.push_back(item); });
      hashed.for_each_near(p, [&](int item) { near_hashed.push_back(item); });
      dense.for_each_within_half_cell(p, [&](int item) { half_dense.push_back(item); });
      hashed.for_each_within_half_cell(p, [&](int item) { half_hashed.push_back(item); });
      ASSERT_EQ(near_dense, near_hashed) << "query " << p.x << ", " << p.y;
      ASSERT_EQ(half_dense, half_hashed) << "query " << p.x << ", " << p.y;
      const std::set<int> found(near_dense.begin(), near_dense.end()), half(half_dense.begin(), half_dense.end());
      for (int i = 0; i < static_cast<int>(segments.size()); ++i) {
        const double d = distance_to_segment(p, segments[i].first, segments[i].second);
        if (d <= cell) {
          EXPECT_TRUE(found.count(i)) << "item " << i << " at " << d;
        }
        if (d <= cell / 2) {
          EXPECT_TRUE(half.count(i)) << "item " << i << " at " << d;
        }
      }
    }
  }
}

TEST(NeighbourGrid, BatchesAppendedInOrderGiveTheGridOfDirectAdds) {
  // The reference adds every segment to the grid itself and sorts on one thread; the others gather
  // contiguous runs of the same segments in 2, 3 and 8 batches and sort on that many threads.
  // Many segments share cells (items in one cell must keep insertion order through the sort).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cell = 1.0;
  std::vector<std::pair<Point, Point>> segments;
  for (int i = 0; i < 30000; ++i) {
    const Point a{30 * unit(rng), 30 * unit(rng)};
    const double length = cell * (i % 50 == 0 ? std::pow(10.0, 3 * unit(rng)) : 2 * unit(rng));
    const double angle = 6.283185307179586 * unit(rng);
    segments.emplace_back(a, Point{a.x + length * std::cos(angle), a.y + length * std::sin(angle)});
  }
  UniformGrid reference(cell);
  for (std::size_t i = 0; i < segments.size(); ++i)
    reference.add_segment(static_cast<int>(i), segments[i].first, segments[i].second);
  reference.finish(1);
  std::vector<Point> queries;
  for (int q = 0; q < 3000; ++q) queries.push_back({-2 + 34 * unit(rng), -2 + 34 * unit(rng)});
  for (const int parts : {1, 2, 3, 8}) {
    UniformGrid grid(cell);
    std::vector<UniformGrid::Batch> batches(static_cast<std::size_t>(parts), UniformGrid::Batch(grid));
    parallel_chunks(segments.size(), parts, [&](std::size_t begin, std::size_t end, int w) {
      for (std::size_t i = begin; i < end; ++i)
        batches[static_cast<std::size_t>(w)].add_segment(static_cast<int>(i), segments[i].first, segments[i].second);
    });
    grid.append(std::move(batches));
    grid.finish(parts);
    for (const Point p : queries) {
      std::vector<int> expected, got, expected_half, got_half;
      reference.for_each_near(p, [&](int item) { expected.push_back(item); });
      grid.for_each_near(p, [&](int item) { got.push_back(item); });
      reference.for_each_within_half_cell(p, [&](int item) { expected_half.push_back(item); });
      grid.for_each_within_half_cell(p, [&](int item) { got_half.push_back(item); });
      ASSERT_EQ(got, expected) << parts << " batches, query " << p.x << ", " << p.y;
      ASSERT_EQ(got_half, expected_half) << parts << " batches, query " << p.x << ", " << p.y;
    }
  }
}

TEST(NeighbourGrid, ParallelStableSortIsStdStableSort) {
  // Few distinct keys: long runs of ties whose order only a stable sort keeps.
  std::mt19937_64 rng(9);
  std::vector<std::pair<int, int>> items;
  for (int i = 0; i < 50000; ++i) items.emplace_back(static_cast<int>(rng() % 97), i);
  const auto by_key = [](const auto& l, const auto& r) { return l.first < r.first; };
  auto expected = items;
  std::stable_sort(expected.begin(), expected.end(), by_key);
  for (const int threads : {1, 2, 3, 8}) {
    auto got = items;
    parallel_stable_sort(got.begin(), got.end(), threads, by_key);
    EXPECT_EQ(got, expected) << threads << " threads";
  }
}

}  // namespace
}  // namespace covmap::cleaning
