// The engine's triangulation layout (engine/regular_triangulation.h) against CGAL's default cells,
// and the exact test of dimension 3 (lifted::span_space). The lean cells drop CGAL's hidden-point
// list; the claim is that nothing else changes, in every dimension: the same cells, with the same
// vertices and neighbours, in the same container order, which decides the order of the engine's
// output. The oracle for span_space is the exact affine rank of the lifted points over Gmpq,
// sharing no code with lifted_traits.cpp.
#include <CGAL/Cartesian.h>
#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <thread>
#include <vector>

#include "site_families.h"
#include "voronoi/engine/regular_triangulation.h"

namespace covmap::voronoi::engine {
namespace {

using testing::Family;
using Q = CGAL::Gmpq;
using QK = CGAL::Cartesian<Q>;

std::vector<RawWeightedPoint> weighted_points(const std::vector<Site>& sites) {
  std::vector<RawWeightedPoint> points;
  for (std::size_t i = 0; i < sites.size(); ++i)
    points.emplace_back(RawPoint(sites[i].x, sites[i].y, sites[i].weight), static_cast<double>(i));
  return points;
}

// Each cell (in dimension 2 each face, in dimension 1 each edge) in container order: its
// vertices' sites (-1: infinite) and, for each neighbour, its position in container order.
template <class Triangulation>
std::vector<std::array<int, 8>> cells_in_order(Triangulation& rt) {
  std::map<typename Triangulation::Cell_handle, int> position;
  int k = 0;
  const auto& tds = rt.tds();
  for (auto c = tds.raw_cells_begin(); c != tds.raw_cells_end(); ++c) position[c] = k++;
  std::vector<std::array<int, 8>> cells;
  for (auto c = tds.raw_cells_begin(); c != tds.raw_cells_end(); ++c) {
    std::array<int, 8> row;
    row.fill(-2);
    for (int i = 0; i <= rt.dimension(); ++i) {
      row[i] = rt.is_infinite(c->vertex(i)) ? -1 : site_of(c->vertex(i));
      row[4 + i] = position.at(c->neighbor(i));
    }
    cells.push_back(row);
  }
  return cells;
}

class SpatialTriangulationTest : public ::testing::TestWithParam<Family> {};

TEST_P(SpatialTriangulationTest, SameCellsInTheSameOrderAsCgalsDefaultCells) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto sites = testing::make_sites(GetParam(), 400, seed);
    const auto points = weighted_points(sites);
    RegularTriangulation regular(points.begin(), points.end());
    SpatialTriangulation spatial(points.begin(), points.end());
    ASSERT_EQ(spatial.dimension(), regular.dimension());
    EXPECT_EQ(cells_in_order(spatial), cells_in_order(regular)) << "seed " << seed;
    EXPECT_TRUE(spatial.is_valid());
  }
}

// build_diagram inserts through insert_spatially_sorted (its own copy of CGAL's range insertion,
// sorting the points in place): the same cells in the same order as the range constructor.
TEST_P(SpatialTriangulationTest, EnginesInsertionGivesTheRangeConstructorsCells) {
  for (const int n : {400, 5000}) {
    const auto sites = testing::make_sites(GetParam(), n, 7);
    const auto points = weighted_points(sites);
    SpatialTriangulation reference(points.begin(), points.end());
    SpatialTriangulation engine;
    auto sorted = points;
    insert_spatially_sorted(engine, sorted);
    ASSERT_EQ(engine.dimension(), reference.dimension());
    EXPECT_EQ(cells_in_order(engine), cells_in_order(reference)) << n << " sites";
  }
}

INSTANTIATE_TEST_SUITE_P(Families, SpatialTriangulationTest,
                         ::testing::Values(Family::UniformWeights, Family::EqualWeights, Family::WeightClasses,
                                           Family::SharedMaximum, Family::Grid, Family::Collinear,
                                           Family::LargeCoordinates),
                         [](const auto& info) { return testing::family_name(info.param); });

TEST(SpatialTriangulationTest, CellsAreSmallerThanCgalsDefault) {
  EXPECT_LT(sizeof(SpatialTriangulation::Triangulation_data_structure::Cell),
            sizeof(RegularTriangulation::Triangulation_data_structure::Cell));
}

// The cells and vertices live in engine/cell_arena.h's huge-page chunks: triangulations built and
// cleared on several threads at once, some in prefaulted chunks, keep their cells (the same as
// CGAL's default allocator gives), and every chunk is returned once the last of them is gone.
TEST(SpatialTriangulationTest, ArenaChunksAreSharedByThreadsAndReturned) {
  ASSERT_EQ(arena_mapped_bytes(), 0u);
  arena_prefault(std::size_t{5} << 20);  // taken by whichever triangulation needs a chunk first
  EXPECT_GE(arena_mapped_bytes(), std::size_t{5} << 20);
  std::vector<std::vector<std::array<int, 8>>> got(3), expected(3);
  std::vector<std::thread> threads;
  for (int t = 0; t < 3; ++t)
    threads.emplace_back([&, t] {
      const auto points = weighted_points(testing::make_sites(Family::UniformWeights, 3000, 10 + t));
      SpatialTriangulation spatial(points.begin(), points.end());
      got[t] = cells_in_order(spatial);
      spatial.clear();
      SpatialTriangulation again(points.begin(), points.end());  // reuses or maps chunks again
      EXPECT_EQ(cells_in_order(again), got[t]);
      RegularTriangulation regular(points.begin(), points.end());
      expected[t] = cells_in_order(regular);
    });
  for (std::thread& t : threads) t.join();
  for (int t = 0; t < 3; ++t) EXPECT_EQ(got[t], expected[t]) << "thread " << t;
  arena_release_prefaulted();
  EXPECT_EQ(arena_mapped_bytes(), 0u);
}

// The exact affine rank of the lifted points c = (x, y, -1/2)/w² is 3.
bool lifted_rank_is_three(const std::vector<RawPoint>& points) {
  std::vector<QK::Point_3> lifted;
  for (const RawPoint& p : points) {
    const Q u = Q(1) / (Q(p.z()) * Q(p.z()));
    lifted.emplace_back(Q(p.x()) * u, Q(p.y()) * u, Q(-1) / Q(2) * u);
  }
  const std::size_t n = lifted.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c)
        for (std::size_t d = c + 1; d < n; ++d)
          if (!CGAL::coplanar(lifted[a], lifted[b], lifted[c], lifted[d])) return true;
  return false;
}

TEST(SpanSpace, AgreesWithTheExactRankOfTheLiftedPoints) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> coord(-4, 4), weight(1, 3), size(1, 9), kind(0, 4);
  int spanning = 0, flat = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    std::vector<RawPoint> points;
    const int k = kind(rng), n = size(rng);
    for (int i = 0; i < n; ++i) {
      const double x = coord(rng), y = k == 1 ? 2 * x - 1 : coord(rng);  // kind 1: collinear sites
      double w = weight(rng);
      if (k == 2) w = 2;                                   // equal weights
      if (k == 3) w = std::sqrt(std::fabs(x + 2 * y) + 1);  // w² affine in position where x + 2y ≥ -1
      if (k == 4) w = i < 3 ? 1.0 : 3.0;                    // few sites of one weight
      points.emplace_back(x, y, w);
    }
    // Distinct positions, as build_diagram guarantees.
    std::sort(points.begin(), points.end(), [](const RawPoint& a, const RawPoint& b) {
      return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
    });
    points.erase(std::unique(points.begin(), points.end(),
                             [](const RawPoint& a, const RawPoint& b) { return a.x() == b.x() && a.y() == b.y(); }),
                 points.end());
    std::shuffle(points.begin(), points.end(), rng);
    const bool expected = lifted_rank_is_three(points);
    std::vector<RawWeightedPoint> weighted;
    for (const RawPoint& p : points) weighted.emplace_back(p, static_cast<double>(weighted.size()));
    ASSERT_EQ(lifted::span_space(weighted), expected) << "trial " << trial;
    (expected ? spanning : flat) += 1;
  }
  EXPECT_GT(spanning, 300);
  EXPECT_GT(flat, 300);
}

}  // namespace
}  // namespace covmap::voronoi::engine
