#include "fitting/inner_ordering.h"

#include <algorithm>
#include <set>
#include <utility>

namespace covmap::fitting::detail {

std::vector<std::vector<int>> independent_rounds(std::size_t site_count, std::span<const BoundarySample> samples,
                                                 std::span<const int> sample_count) {
  std::vector<std::set<int>> neighbours(site_count);
  for (const BoundarySample& s : samples) {
    if (s.site_a == s.site_b || s.site_b == kNone) continue;
    neighbours[s.site_a].insert(s.site_b);
    neighbours[s.site_b].insert(s.site_a);
  }
  std::vector<int> left;
  for (std::size_t i = 0; i < site_count; ++i)
    if (sample_count[i] > 0) left.push_back(static_cast<int>(i));
  std::vector<std::vector<int>> rounds;
  std::vector<char> placed(site_count, 0);
  while (!left.empty()) {
    auto degree = [&](int v) {
      int d = 0;
      for (int w : neighbours[v]) d += !placed[w];
      return d;
    };
    std::vector<std::pair<int, int>> queue;  // (degree, site): ties go to the lower index
    for (int v : left) queue.push_back({degree(v), v});
    std::sort(queue.begin(), queue.end());
    std::vector<char> blocked(site_count, 0);
    std::vector<int> round, rest;
    for (const auto& [d, v] : queue) {
      if (blocked[v]) continue;
      round.push_back(v);
      blocked[v] = 1;
      for (int w : neighbours[v]) blocked[w] = 1;
    }
    for (int v : round) placed[v] = 1;
    for (int v : left)
      if (!placed[v]) rest.push_back(v);
    rounds.push_back(std::move(round));
    left = std::move(rest);
  }
  return rounds;
}

}  // namespace covmap::fitting::detail
