// A minimal fork–join loop for independent per-item work (engine cells and facets, face tracing,
// recognition's checks), at most 8 workers over contiguous chunks; two-thread sorts. Plain std::thread keeps covmap
// free of a thread-pool dependency.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <iterator>
#include <thread>
#include <vector>

#include "core/large_buffer.h"

namespace covmap {


// The machine's cores, at least 1 and at most 8: the most workers any loop here uses.
inline int hardware_workers() {
  return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
}

inline int worker_count(std::size_t items) {
  if (items < 20000) return 1;  // thread start-up costs more than small loops
  return hardware_workers();
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

// Calls f(i) for every i in [0, n) on up to `workers` threads, each taking the next item when it
// is free: for a few items of uneven cost (independent solves), where contiguous chunks would leave
// a thread idle. f must write only to item i's own results; the caller combines them in index
// order, so the outcome does not depend on the thread count.
template <class F>
void parallel_items(std::size_t n, int workers, F&& f) {
  workers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(workers, 1)), n));
  if (workers <= 1) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < n;) f(i);
  };
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work);
  work();
  for (auto& t : threads) t.join();
}

// Sorts the two halves of [first, last) concurrently with sort(begin, end), then merges them
// through a copy of the left half (a large buffer: no fresh 4 KiB pages for it), the left half's
// element first among equals.
template <class It, class Less, class Sort>
void sort_halves_and_merge(It first, It last, Less& less, Sort sort) {
  const It mid = first + (last - first) / 2;
  std::thread left([&] { sort(first, mid); });
  sort(mid, last);
  left.join();
  LargeVector<typename std::iterator_traits<It>::value_type> buffer(std::make_move_iterator(first), std::make_move_iterator(mid));
  std::merge(std::make_move_iterator(buffer.begin()), std::make_move_iterator(buffer.end()), std::make_move_iterator(mid),
             std::make_move_iterator(last), first, less);
}

// Sorts [first, last) with two threads: the halves concurrently, then one merge. Same result as
// std::sort for keys without ties (both orders are then the unique sorted one).
template <class It, class Less = std::less<>>
void parallel_sort(It first, It last, Less less = {}) {
  if (worker_count(static_cast<std::size_t>(last - first)) <= 1) {
    std::sort(first, last, less);
    return;
  }
  sort_halves_and_merge(first, last, less, [&](It b, It e) { std::sort(b, e, less); });
}

// Stable-sorts [first, last) on up to two of `workers` threads, the same way. Same result as
// std::stable_sort whatever the thread count (a stable order is unique; the merge is stable).
template <class It, class Less = std::less<>>
void parallel_stable_sort(It first, It last, int workers, Less less = {}) {
  if (workers <= 1 || worker_count(static_cast<std::size_t>(last - first)) <= 1) {
    std::stable_sort(first, last, less);
    return;
  }
  sort_halves_and_merge(first, last, less, [&](It b, It e) { std::stable_sort(b, e, less); });
}

}  // namespace covmap
