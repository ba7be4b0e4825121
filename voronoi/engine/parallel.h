// A minimal fork–join loop for the engine's independent per-cell and per-facet work. The machine
// has few cores; plain std::thread keeps covmap free of a thread-pool dependency.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace covmap::voronoi::engine {

inline int worker_count(std::size_t items) {
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  if (items < 20000) return 1;  // thread start-up costs more than small loops
  return static_cast<int>(std::min<unsigned>(hw, 8));
}

// Calls f(begin, end, worker) on `workers` contiguous chunks of [0, n), concurrently.
template <class F>
void parallel_chunks(std::size_t n, int workers, F&& f) {
  if (workers <= 1) {
    f(std::size_t{0}, n, 0);
    return;
  }
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w) {
    const std::size_t begin = n * w / workers, end = n * (w + 1) / workers;
    threads.emplace_back([&f, begin, end, w] { f(begin, end, w); });
  }
  for (auto& t : threads) t.join();
}

}  // namespace covmap::voronoi::engine
