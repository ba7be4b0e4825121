#include "voronoi/engine/cell_arena.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "core/large_buffer.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace covmap::voronoi::engine {
namespace {

constexpr std::size_t kAlign = 64;                         // blocks start on cache lines
constexpr std::size_t kMinChunk = kHugePage;               // a small triangulation touches one huge page
constexpr std::size_t kMaxChunk = std::size_t{32} << 20;   // at most ~one block's worth is left unused

std::size_t round_up(std::size_t bytes, std::size_t to) { return (bytes + to - 1) / to * to; }

struct Chunk {
  std::size_t size = 0;
  std::size_t used = 0;  // bytes carved so far, from the start
  std::size_t live = 0;  // blocks not yet freed
};

struct Arena {
  std::mutex mutex;
  std::map<std::uintptr_t, Chunk> chunks;  // by start address
  std::uintptr_t current = 0;              // the chunk blocks are carved from; 0: none
  std::size_t live_bytes = 0;              // in blocks not yet freed, over all chunks
  std::size_t mapped_bytes = 0;            // of all chunks
  std::vector<std::pair<std::uintptr_t, std::size_t>> ready;  // prefaulted chunks, not yet carved
};

// Never destroyed (like core/large_buffer.cpp's cache): a triangulation freed during static
// destruction must still find its chunks.
Arena& arena() {
  static Arena& a = *new Arena;
  return a;
}

// Chunks are mapped directly, not taken from malloc: glibc raises its mmap threshold to the size
// of a mapped block once it is freed (up to 32 MiB), after which the engine's arrays of up to that
// size would come from its heap and stay resident after being freed, raising the peak memory.
void* map_chunk(std::size_t size) {
#if defined(__linux__)
  // Mapped with a huge page to spare and trimmed to a 2 MiB-aligned start.
  void* raw = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto begin = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = round_up(begin, kHugePage);
  if (aligned > begin) munmap(raw, aligned - begin);
  if (const std::size_t tail = begin + kHugePage - aligned) munmap(reinterpret_cast<void*>(aligned + size), tail);
  void* p = reinterpret_cast<void*>(aligned);
#else
  void* p = std::aligned_alloc(kHugePage, size);
  if (!p) throw std::bad_alloc();
#endif
  advise_huge_pages(p, size);
  return p;
}

void unmap_chunk(void* p, std::size_t size) noexcept {
#if defined(__linux__)
  munmap(p, size);
#else
  (void)size;
  std::free(p);
#endif
}

}  // namespace

void* arena_allocate(std::size_t bytes) {
  const std::size_t need = round_up(std::max<std::size_t>(bytes, 1), kAlign);
  Arena& a = arena();
  const std::lock_guard lock(a.mutex);
  if (a.current != 0) {
    Chunk& c = a.chunks.at(a.current);
    if (need <= c.size - c.used) {
      void* p = reinterpret_cast<void*>(a.current + c.used);
      c.used += need;
      ++c.live;
      a.live_bytes += need;
      return p;
    }
  }
  // A new chunk: a prefaulted one if it is large enough, else one twice what is live (a
  // triangulation grows block by block), within the bounds above. The rest of the previous chunk
  // stays unused (its untouched pages cost nothing).
  if (!a.ready.empty() && a.ready.front().second >= need) {
    const auto [base, size] = a.ready.front();
    a.ready.erase(a.ready.begin());
    a.current = base;
    a.chunks[base] = Chunk{size, need, 1};
    a.live_bytes += need;
    return reinterpret_cast<void*>(base);
  }
  const std::size_t size =
      round_up(std::max(std::clamp(2 * a.live_bytes, kMinChunk, kMaxChunk), need), kHugePage);
  void* base = map_chunk(size);
  a.current = reinterpret_cast<std::uintptr_t>(base);
  a.chunks[a.current] = Chunk{size, need, 1};
  a.mapped_bytes += size;
  a.live_bytes += need;
  return base;
}

void arena_deallocate(void* p, std::size_t bytes) noexcept {
  if (!p) return;
  const std::size_t need = round_up(std::max<std::size_t>(bytes, 1), kAlign);
  Arena& a = arena();
  const std::lock_guard lock(a.mutex);
  auto it = std::prev(a.chunks.upper_bound(reinterpret_cast<std::uintptr_t>(p)));
  a.live_bytes -= need;
  if (--it->second.live > 0) return;
  if (a.current == it->first) a.current = 0;
  a.mapped_bytes -= it->second.size;
  unmap_chunk(reinterpret_cast<void*>(it->first), it->second.size);
  a.chunks.erase(it);
}

void arena_prefault(std::size_t bytes) {
  constexpr std::size_t kPage = 4096;
  for (std::size_t done = 0; done < bytes;) {
    const std::size_t size = std::min(kMaxChunk, round_up(bytes - done, kHugePage));
    auto* p = static_cast<volatile char*>(map_chunk(size));
    for (std::size_t at = 0; at < size; at += kPage) p[at] = 0;  // with huge pages, 1 in 512 faults
    Arena& a = arena();
    const std::lock_guard lock(a.mutex);
    a.ready.emplace_back(reinterpret_cast<std::uintptr_t>(p), size);
    a.mapped_bytes += size;
    done += size;
  }
}

void arena_release_prefaulted() noexcept {
  Arena& a = arena();
  const std::lock_guard lock(a.mutex);
  for (const auto& [base, size] : a.ready) {
    unmap_chunk(reinterpret_cast<void*>(base), size);
    a.mapped_bytes -= size;
  }
  a.ready.clear();
}

std::size_t arena_mapped_bytes() {
  Arena& a = arena();
  const std::lock_guard lock(a.mutex);
  return a.mapped_bytes;
}

}  // namespace covmap::voronoi::engine
