#include "core/large_buffer.h"

#include <cstdint>
#include <map>
#include <mutex>
#include <unordered_map>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
#endif

namespace covmap {
namespace {

// Released large blocks are kept for the next large allocation: already faulted in, they cost
// nothing to touch again. Tracing and recognition free and allocate arrays of the same few sizes
// stage after stage (and run after run in a benchmark or a service).
struct BlockCache {
  std::mutex mutex;
  std::multimap<std::size_t, void*> free_blocks;    // size -> block
  std::unordered_map<void*, std::size_t> size_of;  // every live or cached large block
  std::size_t cached = 0;
};

// Never destroyed: a static BlockCache was destroyed at exit, its map freed but not the blocks in
// it (LeakSanitizer reported every kept block as leaked), and a LargeVector freed after that (a
// static one, a thread still running) would have locked a destroyed mutex. Kept blocks now stay
// reachable from here until the process ends.
BlockCache& block_cache() {
  static BlockCache& cache = *new BlockCache;
  return cache;
}

// At most this much memory is kept; a cached block serves requests down to a quarter of its size.
constexpr std::size_t kMaxCached = std::size_t{1} << 30;
constexpr std::size_t kMaxWaste = 4;

void advise(void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: a kernel without transparent huge pages leaves the range as it is.
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kHugePage - 1) / kHugePage * kHugePage;
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) / kHugePage * kHugePage;
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p, (void)bytes;
#endif
}

// Under AddressSanitizer (scripts/sanitize.sh) a kept block is poisoned, and so is the part of a
// block beyond the bytes asked for: ASan sees the whole block as one live allocation, so without
// this a use after deallocate_large, or an overflow into the rounding, would go unnoticed.
void poison(void* p, std::size_t bytes) {
#if defined(__SANITIZE_ADDRESS__)
  ASAN_POISON_MEMORY_REGION(p, bytes);
#else
  (void)p, (void)bytes;
#endif
}
void unpoison(void* p, std::size_t bytes) {
#if defined(__SANITIZE_ADDRESS__)
  ASAN_UNPOISON_MEMORY_REGION(p, bytes);
#else
  (void)p, (void)bytes;
#endif
}

}  // namespace

void advise_huge_pages(void* p, std::size_t bytes) {
  if (bytes >= kLargeBlock) advise(p, bytes);
}

void* allocate_large(std::size_t bytes) {
  if (bytes < kLargeBlock) {
    void* p = std::malloc(bytes > 0 ? bytes : 1);
    if (!p) throw std::bad_alloc();
    return p;
  }
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  BlockCache& cache = block_cache();
  {
    const std::lock_guard lock(cache.mutex);
    const auto it = cache.free_blocks.lower_bound(rounded);
    if (it != cache.free_blocks.end() && it->first / kMaxWaste <= rounded) {
      void* p = it->second;
      cache.cached -= it->first;
      cache.free_blocks.erase(it);
      unpoison(p, bytes);
      return p;
    }
  }
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
  advise(p, rounded);
  poison(static_cast<char*>(p) + bytes, rounded - bytes);
  const std::lock_guard lock(cache.mutex);
  cache.size_of[p] = rounded;
  return p;
}

void deallocate_large(void* p, std::size_t bytes) noexcept {
  if (!p) return;
  if (bytes < kLargeBlock) {
    std::free(p);
    return;
  }
  BlockCache& cache = block_cache();
  const std::lock_guard lock(cache.mutex);
  const std::size_t size = cache.size_of.at(p);
  if (cache.cached + size <= kMaxCached) {
    poison(p, size);
    cache.free_blocks.emplace(size, p);
    cache.cached += size;
    return;
  }
  cache.size_of.erase(p);
  unpoison(p, size);
  std::free(p);
}

void release_large_buffers() noexcept {
  BlockCache& cache = block_cache();
  const std::lock_guard lock(cache.mutex);
  for (const auto& [size, p] : cache.free_blocks) {
    cache.size_of.erase(p);
    unpoison(p, size);
    std::free(p);
  }
  cache.free_blocks.clear();
  cache.cached = 0;
}

}  // namespace covmap
