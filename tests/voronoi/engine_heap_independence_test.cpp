// The engine's output, element order included, must not depend on where the allocator puts its
// data: a service builds diagrams in a long-lived heap, and the same sites must give the same file.
// The property is tested by building once in a fresh state and again with the heap rearranged
// (allocations of the engine's own block sizes held and released around the second build), on
// the inputs whose lifted sites are coplanar — all weights equal, and w² affine in position — for
// which the planar extractor must not take each edge from the face CGAL's edge iterator picks by
// comparing addresses (then the 30×30 equal-weight grid changes order when a small array is freed
// before the triangulation).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "voronoi/engine.h"

namespace covmap::voronoi {
namespace {

std::vector<Site> equal_weight_grid(int side) {
  std::vector<Site> sites;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) sites.push_back({std::to_string(sites.size()), 10.0 * i, 10.0 * j, 1.0});
  return sites;
}

// w² = 1 + x/100 + y/300: the lifted sites span a plane, not space.
std::vector<Site> affine_square_weights(int n) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> at(0.0, 100.0);
  std::vector<Site> sites;
  for (int k = 0; k < n; ++k) {
    const double x = at(rng), y = at(rng);
    sites.push_back({std::to_string(k), x, y, std::sqrt(1.0 + x / 100.0 + y / 300.0)});
  }
  return sites;
}

// Holds allocations of many sizes, every other one released, so the next structures land
// elsewhere and in another relative order than in a quiet heap.
struct HeapShuffle {
  std::vector<std::unique_ptr<char[]>> held;
  explicit HeapShuffle(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> size(16, 1 << 15);
    for (int k = 0; k < 4000; ++k) held.emplace_back(new char[static_cast<std::size_t>(size(rng))]);
    for (std::size_t k = 0; k < held.size(); k += 2) held[k].reset();
  }
};

void expect_same_order(const Diagram& want, const Diagram& got) {
  ASSERT_EQ(got.nodes.size(), want.nodes.size());
  ASSERT_EQ(got.arcs.size(), want.arcs.size());
  for (std::size_t k = 0; k < want.nodes.size(); ++k) {
    EXPECT_EQ(got.nodes[k].x, want.nodes[k].x) << "node " << k;
    EXPECT_EQ(got.nodes[k].y, want.nodes[k].y) << "node " << k;
  }
  for (std::size_t k = 0; k < want.arcs.size(); ++k) {
    EXPECT_EQ(got.arcs[k].left_site, want.arcs[k].left_site) << "arc " << k;
    EXPECT_EQ(got.arcs[k].right_site, want.arcs[k].right_site) << "arc " << k;
    EXPECT_EQ(got.arcs[k].from, want.arcs[k].from) << "arc " << k;
    EXPECT_EQ(got.arcs[k].to, want.arcs[k].to) << "arc " << k;
  }
}

TEST(EngineHeapIndependence, CoplanarLiftedSitesGiveOneOrderWhateverTheHeap) {
  for (const auto& sites : {equal_weight_grid(30), affine_square_weights(400)}) {
    const Diagram first = build_diagram(sites);
    for (unsigned seed : {1u, 2u, 3u}) {
      HeapShuffle shuffle(seed);
      expect_same_order(first, build_diagram(sites));
    }
  }
}

}  // namespace
}  // namespace covmap::voronoi
