#include "voronoi/large_buffer.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace covmap::voronoi {

void* allocate_large(std::size_t bytes) {
  void* p = nullptr;
  if (bytes >= kLargeBlock) {
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    p = std::aligned_alloc(kHugePage, rounded);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: a kernel without transparent huge pages leaves the block as it is.
    if (p) madvise(p, rounded, MADV_HUGEPAGE);
#endif
  } else {
    p = std::malloc(bytes > 0 ? bytes : 1);
  }
  if (!p) throw std::bad_alloc();
  return p;
}

}  // namespace covmap::voronoi
