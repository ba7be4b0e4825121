// Memory for the blocks in which CGAL's Compact_container keeps the triangulation's cells and
// vertices (internal to the engine; regular_triangulation.h routes SpatialTriangulation's blocks
// here).
//
// Why: inserting a site walks from cell to cell through tens of MB of cells in no particular
// order, and the container grows by blocks of 16 more cells each time, each from malloc: 4 KiB
// pages, faulted in one by one on the inserting thread, and a TLB miss on most steps of the walk.
// Here the blocks are carved from chunks of up to 32 MiB that are 2 MiB-aligned and advised as
// transparent huge pages (as core/large_buffer.h does for the engine's arrays): a small fraction
// of the faults, and the walk's working set within the TLB's reach (docs/PERFORMANCE.md).
//
// Only where blocks lie changes, not which cells they hold or their order: the container hands
// out its slots (free list first, then the next fresh slot) and iterates them (block after block)
// without regard to addresses, and the engine numbers cells in that order. A chunk goes back to
// the system as soon as its last block is freed (clearing the triangulation frees them all).
// Thread-safe; blocks may be freed on another thread than the one that allocated them.
#pragma once

#include <cstddef>
#include <new>
#include <type_traits>

namespace covmap::voronoi::engine {

void* arena_allocate(std::size_t bytes);
void arena_deallocate(void* p, std::size_t bytes) noexcept;

// Maps chunks for `bytes` more of blocks and touches every page of them, for the blocks allocated
// next: build_diagram calls it on its second thread as the insertion starts, so that the inserting
// thread finds its memory faulted in rather than zeroing fresh pages itself. A chunk still being
// touched is not handed out; the allocator maps its own then.
void arena_prefault(std::size_t bytes);

// Unmaps the prefaulted chunks no block was carved from.
void arena_release_prefaulted() noexcept;

// Bytes of the chunks currently mapped, prefaulted ones included (for tests: 0 when no
// triangulation is alive and none are prefaulted).
std::size_t arena_mapped_bytes();

// An allocator over the arena, shaped as std::allocator (stateless, all instances equal): the
// members of regular_triangulation.h's std::allocator specializations.
template <class T>
struct ArenaAllocator {
  using value_type = T;
  using size_type = std::size_t;
  using difference_type = std::ptrdiff_t;
  using propagate_on_container_move_assignment = std::true_type;
  using is_always_equal = std::true_type;

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(arena_allocate(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { arena_deallocate(p, n * sizeof(T)); }
};

}  // namespace covmap::voronoi::engine
