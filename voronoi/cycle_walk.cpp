// The cycle walk of trace_faces(): the closed cycles of the continuations, in the order of their
// smallest half-arc. The walk only follows next_half (memory latency bound); orientation and the
// rest are computed per cycle afterwards, in parallel (cycle_orientation.cpp).
#include <algorithm>
#include <atomic>
#include <vector>

#include "core/parallel.h"
#include "voronoi/face_tracing.h"

namespace covmap::voronoi::tracing {
namespace {

void walk_sequentially(const Diagram& d, bool by_sites, const LargeVector<int>& next_half, LargeVector<char>& seen,
                       CycleSet& cs) {
  const int halves = static_cast<int>(next_half.size());
  LargeVector<Cycle>& cycles = cs.cycles;
  LargeVector<int>& cycle_halves = cs.cycle_halves;
  for (int h0 = 0; h0 < halves; ++h0) {
    if (seen[h0] || label(d, by_sites, h0) == kNone) continue;
    Cycle cyc;
    cyc.site = label(d, by_sites, h0);
    cyc.begin = static_cast<int>(cycle_halves.size());
    int h = h0;
    bool closed = false;
    for (int guard = 0; guard <= halves; ++guard) {
      seen[h] = 1;
      cycle_halves.push_back(h);
      const int nx = next_half[h];
      if (nx < 0) break;
      if (nx == h0) {
        closed = true;
        break;
      }
      if (seen[nx]) break;
      h = nx;
    }
    if (!closed) {
      cycle_halves.resize(cyc.begin);
      continue;
    }
    cyc.end = static_cast<int>(cycle_halves.size());
    cycles.push_back(cyc);
  }
}

// By geometry next_half is a permutation of the half-arcs (every half-arc has one successor and
// one predecessor), and its cycles can be walked in parallel: each cycle by the worker whose
// range holds its smallest half-arc, which is where the sequential walk starts it too, so the
// cycles come out in the same order. A walk from any other half-arc stops at the first smaller
// one. Anything but a permutation (a dangling end, a walk that does not come back) is left to the
// sequential walk.
bool walk_in_parallel(const LargeVector<int>& next_half, LargeVector<char>& seen, CycleSet& cs) {
  const int halves = static_cast<int>(next_half.size());
  LargeVector<Cycle>& cycles = cs.cycles;
  LargeVector<int>& cycle_halves = cs.cycle_halves;
  const int workers = worker_count(static_cast<std::size_t>(halves));
  std::vector<LargeVector<Cycle>> found(workers);
  std::vector<LargeVector<int>> walked(workers);
  std::atomic<bool> malformed{false};
  parallel_chunks(static_cast<std::size_t>(halves), workers, [&](std::size_t b, std::size_t e, int w) {
    LargeVector<int>& out = walked[w];
    out.reserve(e - b + 64);  // the cycles owned by a range have about as many half-arcs as it
    found[w].reserve((e - b) / 2);
    for (int h0 = static_cast<int>(b); h0 < static_cast<int>(e) && !malformed.load(std::memory_order_relaxed); ++h0) {
      if (std::atomic_ref<char>(seen[h0]).load(std::memory_order_relaxed)) continue;
      const std::size_t begin = out.size();
      int h = h0;
      bool owner = false;
      for (int guard = 0;; ++guard) {
        out.push_back(h);
        const int nx = next_half[h];
        if (nx < 0 || guard > halves) {
          malformed = true;
          break;
        }
        if (nx == h0) {
          owner = true;
          break;
        }
        if (nx < h0) break;  // the cycle's walk starts at a smaller half-arc
        h = nx;
      }
      if (!owner) {
        out.resize(begin);
        continue;
      }
      for (std::size_t k = begin; k < out.size(); ++k) std::atomic_ref<char>(seen[out[k]]).store(1, std::memory_order_relaxed);
      found[w].push_back(Cycle{0, static_cast<int>(begin), static_cast<int>(out.size()), false, 0.0});
    }
  });
  if (malformed) {
    std::fill(seen.begin(), seen.end(), 0);
    return false;
  }
  for (int w = 0; w < workers; ++w) {
    const int offset = static_cast<int>(cycle_halves.size());
    cycle_halves.insert(cycle_halves.end(), walked[w].begin(), walked[w].end());
    for (Cycle c : found[w]) {
      c.begin += offset, c.end += offset;
      cycles.push_back(c);
    }
  }
  return true;
}

}  // namespace

CycleSet walk_cycles(const Diagram& d, bool by_sites, const LargeVector<int>& next_half) {
  const int halves = static_cast<int>(next_half.size());
  CycleSet cs;
  cs.cycles.reserve(static_cast<std::size_t>(halves) / 2);  // a hint: most cycles have two or more half-arcs
  cs.cycle_halves.reserve(halves);
  LargeVector<char> seen(halves, 0);
  if (by_sites || !walk_in_parallel(next_half, seen, cs)) walk_sequentially(d, by_sites, next_half, seen, cs);
  return cs;
}

}  // namespace covmap::voronoi::tracing
