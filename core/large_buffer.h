// Storage for the large temporary arrays of face tracing and recognition (one entry per arc or
// half-arc: tens of MB at 10^6 faces).
//
// Why: the first touch of every fresh 4 KiB page is a page fault, and on virtual machines faults
// cost enough that a large recognition can spend more time in them than computing
// (docs/PERFORMANCE.md). Blocks of at least kLargeBlock bytes are therefore aligned to 2 MiB and
// advised as transparent huge pages (Linux, THP mode "madvise" or "always"): one fault per 2 MiB.
// Elsewhere, or when the kernel declines, they are ordinary allocations.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace covmap {

inline constexpr std::size_t kHugePage = std::size_t{2} << 20;
inline constexpr std::size_t kLargeBlock = std::size_t{1} << 20;

// Blocks of at least kLargeBlock bytes are aligned to kHugePage and advised as huge pages; released
// ones are kept (up to 1 GiB) and handed out again, already faulted in, for later requests of up to
// their size — the arrays of one recognition are freed and allocated stage after stage, and a
// benchmark or a service recognizes graph after graph. Smaller blocks are plain malloc/free.
// Thread-safe. `bytes` must be the same in both calls.
void* allocate_large(std::size_t bytes);
void deallocate_large(void* p, std::size_t bytes) noexcept;

// Returns the kept blocks to the system (a long-running process after its largest job).
void release_large_buffers() noexcept;

// Advises the 2 MiB-aligned interior of [p, p + bytes) as huge pages when bytes >= kLargeBlock:
// for large std::vector results (reserved, not yet written) that must keep the standard allocator.
void advise_huge_pages(void* p, std::size_t bytes);

// Note: vectors sized without a value (v(n), resize(n)) are default-initialised, not zeroed, like
// new T[n]: the zero fill would be the first touch of every page, on one core, right before the
// parallel loop that writes the values anyway.
template <class T>
struct LargeAllocator {
  using value_type = T;
  LargeAllocator() noexcept = default;
  template <class U>
  LargeAllocator(const LargeAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocate_large(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { deallocate_large(p, n * sizeof(T)); }
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const LargeAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using LargeVector = std::vector<T, LargeAllocator<T>>;

}  // namespace covmap
