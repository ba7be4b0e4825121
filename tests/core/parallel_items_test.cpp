// core/parallel.h's parallel_items: every item exactly once, whatever the number of workers
// (including more workers than items and none to do), and the calls really spread over threads.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "core/parallel.h"

namespace covmap {
namespace {

TEST(ParallelItems, EveryItemExactlyOnce) {
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{5}, std::size_t{1000}})
    for (int workers : {0, 1, 2, 3, 16}) {
      std::vector<std::atomic<int>> calls(n);
      parallel_items(n, workers, [&](std::size_t i) { calls[i].fetch_add(1); });
      for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(calls[i].load(), 1) << "n " << n << " workers " << workers << " item " << i;
    }
}

TEST(ParallelItems, SeveralWorkersRunOnSeveralThreads) {
  // Each item waits until two distinct threads have started items: only concurrent workers pass.
  std::mutex m;
  std::set<std::thread::id> seen;
  std::atomic<bool> two{false};
  parallel_items(2, 2, [&](std::size_t) {
    {
      std::lock_guard lock(m);
      seen.insert(std::this_thread::get_id());
      if (seen.size() >= 2) two = true;
    }
    for (int spin = 0; spin < 2000 && !two; ++spin) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  EXPECT_TRUE(two.load());
}

}  // namespace
}  // namespace covmap
