// Tracing a raster's regions (gis/pixel_regions.h) against independent oracles: a brute-force
// breadth-first labelling of 4-connected components, even-odd point-in-polygon at every pixel
// centre, shoelace areas against pixel counts, ring simplicity and orientation checked from the
// vertices, and each polygon's edges against its component's boundary counted pixel by pixel.
// Hand cases give the expected rings worked out on paper.
#include "gis/pixel_regions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <optional>
#include <queue>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace covmap::gis {
namespace {

// ---- Oracles ----------------------------------------------------------------------------------

// 4-connected components by breadth-first search; label -1 for nodata.
struct Oracle {
  std::vector<int> label;
  std::vector<std::int64_t> size;
  std::vector<std::int64_t> value;
};

Oracle flood_fill(const PixelGrid& g) {
  Oracle o;
  o.label.assign(g.values.size(), -1);
  for (int start = 0; start < g.width * g.height; ++start) {
    if (o.label[start] >= 0 || (g.nodata && g.values[start] == *g.nodata)) continue;
    const int id = static_cast<int>(o.size.size());
    o.size.push_back(0);
    o.value.push_back(g.values[start]);
    std::queue<int> queue;
    queue.push(start);
    o.label[start] = id;
    while (!queue.empty()) {
      const int p = queue.front();
      queue.pop();
      ++o.size[id];
      const int c = p % g.width, r = p / g.width;
      const std::array<std::pair<int, int>, 4> neighbours = {{{c - 1, r}, {c + 1, r}, {c, r - 1}, {c, r + 1}}};
      for (const auto& [nc, nr] : neighbours) {
        if (nc < 0 || nr < 0 || nc >= g.width || nr >= g.height) continue;
        const int q = nr * g.width + nc;
        if (o.label[q] < 0 && g.values[q] == g.values[start]) {
          o.label[q] = id;
          queue.push(q);
        }
      }
    }
  }
  return o;
}

// Twice the shoelace area in (col, row) coordinates.
std::int64_t twice_area(const PixelRing& ring) {
  std::int64_t sum = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const PixelCorner& a = ring[i];
    const PixelCorner& b = ring[(i + 1) % ring.size()];
    sum += a.col * b.row - b.col * a.row;
  }
  return sum;
}

// Even-odd: crossings of a ray from the centre of pixel (c, r) towards +col, over all rings. In
// doubled coordinates the centre is odd and corners even, so the ray never meets a vertex.
bool centre_inside(const PixelPolygon& polygon, std::int64_t c, std::int64_t r) {
  const std::int64_t px = 2 * c + 1, py = 2 * r + 1;
  int crossings = 0;
  auto count = [&](const PixelRing& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const PixelCorner& a = ring[i];
      const PixelCorner& b = ring[(i + 1) % ring.size()];
      if (a.col != b.col || 2 * a.col < px) continue;
      if (std::min(2 * a.row, 2 * b.row) < py && py < std::max(2 * a.row, 2 * b.row)) ++crossings;
    }
  };
  count(polygon.outer);
  for (const PixelRing& hole : polygon.holes) count(hole);
  return crossings % 2 == 1;
}

// Directed unit edges (from corner, to corner).
using UnitEdge = std::array<std::int64_t, 4>;

// The edges of each component pixel facing a pixel outside the component, walked with the pixel
// on the right (clockwise on screen, row down).
std::set<UnitEdge> component_boundary(const PixelGrid& g, const Oracle& o, int id) {
  std::set<UnitEdge> edges;
  auto other = [&](std::int64_t c, std::int64_t r) {
    return c < 0 || r < 0 || c >= g.width || r >= g.height || o.label[r * g.width + c] != id;
  };
  for (std::int64_t r = 0; r < g.height; ++r)
    for (std::int64_t c = 0; c < g.width; ++c) {
      if (o.label[r * g.width + c] != id) continue;
      if (other(c, r - 1)) edges.insert({c, r, c + 1, r});
      if (other(c + 1, r)) edges.insert({c + 1, r, c + 1, r + 1});
      if (other(c, r + 1)) edges.insert({c + 1, r + 1, c, r + 1});
      if (other(c - 1, r)) edges.insert({c, r + 1, c, r});
    }
  return edges;
}

// Adds the ring's unit edges to `edges`; false if one was already there.
bool add_unit_edges(const PixelRing& ring, std::set<UnitEdge>& edges) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    PixelCorner a = ring[i];
    const PixelCorner& b = ring[(i + 1) % ring.size()];
    while (!(a == b)) {
      const PixelCorner n{a.col + (b.col > a.col) - (b.col < a.col), a.row + (b.row > a.row) - (b.row < a.row)};
      if (!edges.insert({a.col, a.row, n.col, n.row}).second) return false;
      a = n;
    }
  }
  return true;
}

// Simple, axis-parallel, alternating, starting at the smallest (row, col) corner, oriented as
// documented (sign +1 for outer rings, -1 for holes).
testing::AssertionResult well_formed_ring(const PixelRing& ring, int sign) {
  if (ring.size() < 4 || ring.size() % 2 != 0) return testing::AssertionFailure() << ring.size() << " vertices";
  std::set<std::pair<std::int64_t, std::int64_t>> seen;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const PixelCorner& a = ring[i];
    const PixelCorner& b = ring[(i + 1) % ring.size()];
    const PixelCorner& c = ring[(i + 2) % ring.size()];
    if (!seen.insert({a.row, a.col}).second) return testing::AssertionFailure() << "corner visited twice";
    const bool ab_horizontal = a.row == b.row && a.col != b.col;
    const bool ab_vertical = a.col == b.col && a.row != b.row;
    const bool bc_horizontal = b.row == c.row && b.col != c.col;
    if (!ab_horizontal && !ab_vertical) return testing::AssertionFailure() << "edge not axis-parallel";
    if (ab_horizontal == bc_horizontal) return testing::AssertionFailure() << "collinear vertex or non-turn";
    if (std::pair(a.row, a.col) < std::pair(ring[0].row, ring[0].col))
      return testing::AssertionFailure() << "ring does not start at its smallest corner";
  }
  if (twice_area(ring) * sign <= 0) return testing::AssertionFailure() << "wrong orientation";
  return testing::AssertionSuccess();
}

// ---- The full check ---------------------------------------------------------------------------

// One polygon against the oracle: well-formed rings; the pixels whose centres it contains form
// exactly one oracle component of its value, whose pixel count is its area and whose boundary
// edges are its rings' edges. Returns the component id (or -1), and counts the covered pixels.
int check_polygon(const PixelGrid& g, const Oracle& o, std::int64_t value, const PixelPolygon& polygon,
                  std::vector<int>& covered) {
  EXPECT_TRUE(well_formed_ring(polygon.outer, +1));
  std::int64_t area2 = twice_area(polygon.outer);
  for (const PixelRing& hole : polygon.holes) {
    EXPECT_TRUE(well_formed_ring(hole, -1));
    area2 += twice_area(hole);
  }
  std::set<int> labels;
  std::int64_t inside = 0;
  for (int r = 0; r < g.height; ++r)
    for (int c = 0; c < g.width; ++c)
      if (centre_inside(polygon, c, r)) {
        ++inside;
        ++covered[r * g.width + c];
        labels.insert(o.label[r * g.width + c]);
      }
  if (labels.size() != 1 || *labels.begin() < 0) {
    ADD_FAILURE() << "polygon of value " << value << " covers " << labels.size() << " components";
    return -1;
  }
  const int id = *labels.begin();
  EXPECT_EQ(o.value[id], value);
  EXPECT_EQ(inside, o.size[id]);
  EXPECT_EQ(area2, 2 * o.size[id]);
  std::set<UnitEdge> edges;
  bool disjoint = add_unit_edges(polygon.outer, edges);
  for (const PixelRing& hole : polygon.holes) disjoint = add_unit_edges(hole, edges) && disjoint;
  EXPECT_TRUE(disjoint) << "two rings of one polygon share an edge";
  EXPECT_EQ(edges, component_boundary(g, o, id));
  return id;
}

void check_regions(const PixelGrid& g, const std::vector<PixelRegions>& regions) {
  SCOPED_TRACE("grid " + std::to_string(g.width) + " x " + std::to_string(g.height));
  const Oracle o = flood_fill(g);
  std::set<std::int64_t> expected_values(o.value.begin(), o.value.end());
  std::vector<int> covered(g.values.size(), 0);
  std::set<int> components_seen;
  std::vector<std::int64_t> values;
  for (const PixelRegions& region : regions) {
    values.push_back(region.value);
    const auto count = std::count(o.value.begin(), o.value.end(), region.value);
    EXPECT_EQ(static_cast<std::int64_t>(region.polygons.size()), count) << "value " << region.value;
    int previous = -1;
    for (const PixelPolygon& polygon : region.polygons) {
      const int id = check_polygon(g, o, region.value, polygon, covered);
      EXPECT_TRUE(components_seen.insert(id).second) << "two polygons for one component";
      EXPECT_GT(id, previous) << "polygons not in row-major order of first pixel";  // oracle ids are
      previous = id;  // numbered in that order too
    }
  }
  EXPECT_TRUE(std::is_sorted(values.begin(), values.end()));
  EXPECT_EQ(std::set<std::int64_t>(values.begin(), values.end()), expected_values);
  EXPECT_EQ(values.size(), expected_values.size());
  for (std::size_t p = 0; p < g.values.size(); ++p)
    EXPECT_EQ(covered[p], o.label[p] < 0 ? 0 : 1) << "pixel " << p << " covered by " << covered[p] << " polygons";
}

// ---- Hand cases -------------------------------------------------------------------------------

PixelGrid grid_of(int width, int height, std::vector<std::int64_t> values, std::optional<std::int64_t> nodata = {}) {
  return PixelGrid{width, height, std::move(values), nodata};
}

PixelRing square(std::int64_t c0, std::int64_t r0, std::int64_t c1, std::int64_t r1, bool clockwise) {
  if (clockwise) return {{c0, r0}, {c1, r0}, {c1, r1}, {c0, r1}};
  return {{c0, r0}, {c0, r1}, {c1, r1}, {c1, r0}};
}

// The traced regions equal `expected` vertex for vertex, and pass the oracle checks.
void expect_traced(const PixelGrid& g, const std::vector<PixelRegions>& expected) {
  const auto regions = trace_pixel_regions(g);
  ASSERT_EQ(regions.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(regions[i].value, expected[i].value);
    ASSERT_EQ(regions[i].polygons.size(), expected[i].polygons.size()) << "value " << expected[i].value;
    for (std::size_t k = 0; k < expected[i].polygons.size(); ++k) {
      EXPECT_EQ(regions[i].polygons[k].outer, expected[i].polygons[k].outer) << "value " << expected[i].value;
      EXPECT_EQ(regions[i].polygons[k].holes, expected[i].polygons[k].holes) << "value " << expected[i].value;
    }
  }
  check_regions(g, regions);
}

TEST(PixelRegions, SinglePixel) { expect_traced(grid_of(1, 1, {7}), {{7, {{square(0, 0, 1, 1, true), {}}}}}); }

TEST(PixelRegions, RingWithAHole) {
  expect_traced(grid_of(3, 3, {1, 1, 1, 1, 2, 1, 1, 1, 1}),
                {{1, {{square(0, 0, 3, 3, true), {square(1, 1, 2, 2, false)}}}},
                 {2, {{square(1, 1, 2, 2, true), {}}}}});
}

TEST(PixelRegions, HoleWithAnIslandOfAThirdValue) {
  // 1 frames a ring of 2, which frames one pixel of 3.
  std::vector<std::int64_t> v(25, 1);
  for (int r = 1; r <= 3; ++r)
    for (int c = 1; c <= 3; ++c) v[r * 5 + c] = (r == 2 && c == 2) ? 3 : 2;
  expect_traced(grid_of(5, 5, v), {{1, {{square(0, 0, 5, 5, true), {square(1, 1, 4, 4, false)}}}},
                                   {2, {{square(1, 1, 4, 4, true), {square(2, 2, 3, 3, false)}}}},
                                   {3, {{square(2, 2, 3, 3, true), {}}}}});
}

TEST(PixelRegions, TwoByTwoCheckerboardIsFourPolygons) {
  // Each value's two pixels touch at the centre corner only; of value 2, row 0 comes first.
  expect_traced(grid_of(2, 2, {1, 2, 2, 1}),
                {{1, {{square(0, 0, 1, 1, true), {}}, {square(1, 1, 2, 2, true), {}}}},
                 {2, {{square(1, 0, 2, 1, true), {}}, {square(0, 1, 1, 2, true), {}}}}});
}

TEST(PixelRegions, PinchWithinOneComponentSplitsOuterRingFromHole) {
  // 1 1 1
  // 1 0 1    the 1s are one component; at corner (1, 2) it holds (0, 1) and (1, 2) diagonally:
  // 0 1 1    the hole around (1, 1) touches the outer ring there.
  const PixelRing outer = {{0, 0}, {3, 0}, {3, 3}, {1, 3}, {1, 2}, {0, 2}};
  expect_traced(grid_of(3, 3, {1, 1, 1, 1, 0, 1, 0, 1, 1}),
                {{0, {{square(1, 1, 2, 2, true), {}}, {square(0, 2, 1, 3, true), {}}}},
                 {1, {{outer, {square(1, 1, 2, 2, false)}}}}});
}

TEST(PixelRegions, AllNodataIsEmpty) {
  EXPECT_TRUE(trace_pixel_regions(grid_of(3, 2, std::vector<std::int64_t>(6, -9999), -9999)).empty());
  EXPECT_TRUE(trace_pixel_regions(grid_of(0, 5, {})).empty());
}

TEST(PixelRegions, NodataHoleAndNoNodataValue) {
  // Without a nodata value, -9999 is an ordinary value.
  const std::vector<std::int64_t> v = {4, 4, 4, 4, -9999, 4, 4, 4, 4};
  const auto with = trace_pixel_regions(grid_of(3, 3, v, -9999));
  ASSERT_EQ(with.size(), 1u);
  EXPECT_EQ(with[0].polygons[0].holes, std::vector<PixelRing>{square(1, 1, 2, 2, false)});
  const auto without = trace_pixel_regions(grid_of(3, 3, v));
  ASSERT_EQ(without.size(), 2u);
  EXPECT_EQ(without[0].value, -9999);
}

TEST(PixelRegions, RejectsInvalidGrids) {
  EXPECT_THROW(trace_pixel_regions(grid_of(3, 3, std::vector<std::int64_t>(8, 0))), std::invalid_argument);
  EXPECT_THROW(trace_pixel_regions(grid_of(-1, 3, {})), std::invalid_argument);
  EXPECT_THROW(trace_pixel_regions(grid_of(2, -2, {})), std::invalid_argument);
  try {
    trace_pixel_regions(grid_of(4, 2, std::vector<std::int64_t>(7, 0)));
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("7 values"), std::string::npos) << e.what();
  }
}

// ---- Random grids -----------------------------------------------------------------------------

enum class Pattern { uniform, checkerboard, blobs };

PixelGrid random_grid(std::mt19937_64& rng, int width, int height, Pattern pattern) {
  std::uniform_int_distribution<int> palette_size(1, 4);
  const int palette = palette_size(rng);
  std::uniform_int_distribution<std::int64_t> any_value(0, palette - 1);
  std::bernoulli_distribution flip(0.2), hole(0.1);
  const bool with_nodata = std::bernoulli_distribution(0.5)(rng);
  PixelGrid g{width, height, {}, with_nodata ? std::optional<std::int64_t>(-1) : std::nullopt};
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      std::int64_t v = 0;
      switch (pattern) {
        case Pattern::uniform: v = any_value(rng); break;
        case Pattern::checkerboard: v = flip(rng) ? any_value(rng) : (c + r) % 2; break;
        case Pattern::blobs: v = hole(rng) ? any_value(rng) : (c / 3 + r / 3) % palette; break;
      }
      if (with_nodata && hole(rng)) v = -1;
      g.values.push_back(v);
    }
  return g;
}

TEST(PixelRegions, RandomGridsAgainstBruteForce) {
  std::mt19937_64 rng(14);
  std::uniform_int_distribution<int> side(1, 16);
  for (int trial = 0; trial < 1500; ++trial) {
    const auto pattern = static_cast<Pattern>(trial % 3);
    int width = side(rng), height = side(rng);
    if (trial % 10 == 0) width = 1;  // single columns and rows
    if (trial % 10 == 1) height = 1;
    const PixelGrid g = random_grid(rng, width, height, pattern);
    SCOPED_TRACE("trial " + std::to_string(trial));
    check_regions(g, trace_pixel_regions(g));
    if (testing::Test::HasFailure()) break;
  }
}

TEST(PixelRegions, IsDeterministic) {
  std::mt19937_64 rng(3);
  const PixelGrid g = random_grid(rng, 40, 30, Pattern::checkerboard);
  expect_traced(g, trace_pixel_regions(g));
}

// ---- A large grid -----------------------------------------------------------------------------

// 2000 x 2000 pixels of nearest-seed regions from 50 random seeds, with no coverage beyond a
// radius and one pixel in 500 replaced by another seed or no coverage (islands, holes, pinches):
// checked by polygon count and area per component (the oracle numbers components of a
// value in the same row-major order the polygons are documented to follow).
TEST(PixelRegions, LargeVoronoiGridByAreaAndCount) {
  constexpr int kSide = 2000, kSeeds = 50;
  constexpr std::int64_t kNoCoverage = -1, kRange2 = 300 * 300;
  std::mt19937_64 rng(50);
  std::uniform_int_distribution<int> coordinate(0, kSide - 1), any_seed(-1, kSeeds - 1);
  std::bernoulli_distribution speck(0.002);
  std::vector<std::pair<std::int64_t, std::int64_t>> seeds(kSeeds);
  for (auto& s : seeds) s = {coordinate(rng), coordinate(rng)};
  PixelGrid g{kSide, kSide, std::vector<std::int64_t>(std::size_t{kSide} * kSide), kNoCoverage};
  for (std::int64_t r = 0; r < kSide; ++r)
    for (std::int64_t c = 0; c < kSide; ++c) {
      std::int64_t best = kNoCoverage, best_d2 = kRange2;
      for (int k = 0; k < kSeeds; ++k) {
        const std::int64_t d2 = (c - seeds[k].first) * (c - seeds[k].first) + (r - seeds[k].second) * (r - seeds[k].second);
        if (d2 < best_d2) best = k, best_d2 = d2;
      }
      g.values[r * kSide + c] = speck(rng) ? any_seed(rng) : best;
    }
  const auto start = std::chrono::steady_clock::now();
  const auto regions = trace_pixel_regions(g);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "trace_pixel_regions on " << kSide << " x " << kSide << " pixels: " << seconds << " s\n";

  const Oracle o = flood_fill(g);
  std::size_t polygons = 0, holes = 0;
  for (const PixelRegions& region : regions) {
    std::vector<int> ids;  // the oracle's components of this value, in row-major order
    for (int id = 0; id < static_cast<int>(o.value.size()); ++id)
      if (o.value[id] == region.value) ids.push_back(id);
    ASSERT_EQ(region.polygons.size(), ids.size()) << "value " << region.value;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const PixelPolygon& polygon = region.polygons[k];
      ASSERT_TRUE(well_formed_ring(polygon.outer, +1));
      std::int64_t area2 = twice_area(polygon.outer);
      for (const PixelRing& hole : polygon.holes) {
        ASSERT_TRUE(well_formed_ring(hole, -1));
        area2 += twice_area(hole);
      }
      EXPECT_EQ(area2, 2 * o.size[ids[k]]) << "value " << region.value << " polygon " << k;
      holes += polygon.holes.size();
    }
    polygons += ids.size();
  }
  EXPECT_EQ(polygons, o.value.size());
  std::cout << regions.size() << " values, " << polygons << " polygons, " << holes << " holes\n";
}

}  // namespace
}  // namespace covmap::gis
