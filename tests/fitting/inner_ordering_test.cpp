// The inner-iteration groups against their definition: independent sets covering every sampled
// site once, filled by fewest remaining neighbours with ties to the lower index.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>
#include <vector>

#include "fitting/inner_ordering.h"

namespace covmap::fitting::detail {
namespace {

std::vector<BoundarySample> edges(const std::vector<std::pair<int, int>>& pairs) {
  std::vector<BoundarySample> out;
  for (const auto& [a, b] : pairs) out.push_back({Point{0, 0}, a, b});
  return out;
}

TEST(InnerOrdering, PathOfFourByHand) {
  // 0-1-2-3: degrees 1 2 2 1. Round 1 takes 0 (lowest degree, lowest index), which blocks 1, then
  // 3, which blocks 2. Then 1 and 2 have one neighbour left each: 1 goes first and blocks 2.
  const auto samples = edges({{0, 1}, {1, 2}, {2, 3}});
  const std::vector<int> count = {1, 2, 2, 1};
  const auto rounds = independent_rounds(4, samples, count);
  const std::vector<std::vector<int>> want = {{0, 3}, {1}, {2}};
  EXPECT_EQ(rounds, want);
}

TEST(InnerOrdering, SitesWithoutSamplesAreLeftOutAndSelfSamplesMakeNoNeighbours) {
  const auto samples = edges({{0, 0}, {2, 2}});
  const std::vector<int> count = {1, 0, 1};
  const auto rounds = independent_rounds(3, samples, count);
  const std::vector<std::vector<int>> want = {{0, 2}};
  EXPECT_EQ(rounds, want);
}

TEST(InnerOrdering, RandomGraphsGiveIndependentRoundsCoveringEverySampledSite) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 5 + static_cast<int>(rng() % 60);
    std::vector<std::pair<int, int>> pairs;
    std::vector<int> count(n, 0);
    for (int k = 0; k < 3 * n; ++k) {
      const int a = static_cast<int>(rng() % n), b = static_cast<int>(rng() % n);
      if (a == b) continue;
      pairs.push_back({a, b});
      ++count[a], ++count[b];
    }
    const auto samples = edges(pairs);
    const auto rounds = independent_rounds(n, samples, count);
    std::vector<int> round_of(n, -1);
    for (std::size_t r = 0; r < rounds.size(); ++r)
      for (int v : rounds[r]) {
        ASSERT_EQ(round_of[v], -1) << "site " << v << " in two rounds";
        round_of[v] = static_cast<int>(r);
      }
    for (int v = 0; v < n; ++v) EXPECT_EQ(round_of[v] >= 0, count[v] > 0) << "site " << v;
    for (const auto& [a, b] : pairs) EXPECT_NE(round_of[a], round_of[b]) << a << " and " << b << " share a round";
  }
}

}  // namespace
}  // namespace covmap::fitting::detail
