// Large buffers (core/large_buffer.h) and the two-core sort (core/parallel.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "core/parallel.h"
#include "core/large_buffer.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
#endif

namespace covmap::voronoi {
namespace {

TEST(LargeBuffer, ReleasedBlocksAreReusedAndHoldWhatIsWritten) {
  release_large_buffers();
  const std::size_t n = (std::size_t{8} << 20) / sizeof(std::uint64_t);  // 8 MiB: a large block
  const std::uint64_t* first = nullptr;
  {
    LargeVector<std::uint64_t> v(n, 7);
    first = v.data();
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(first) % kHugePage, 0u) << "large blocks are 2 MiB aligned";
    EXPECT_TRUE(std::all_of(v.begin(), v.end(), [](std::uint64_t x) { return x == 7; }));
  }
  {
    // The same size again is served from the kept block; its contents are what this vector writes.
    LargeVector<std::uint64_t> w(n, 11);
    EXPECT_EQ(w.data(), first);
    EXPECT_TRUE(std::all_of(w.begin(), w.end(), [](std::uint64_t x) { return x == 11; }));
    // A second live block cannot be the same one.
    LargeVector<std::uint64_t> x(n, 13);
    EXPECT_NE(x.data(), w.data());
  }
  // Small vectors are plain allocations and work like any other.
  LargeVector<int> small = {1, 2, 3};
  small.push_back(4);
  EXPECT_EQ(small.size(), 4u);
  EXPECT_EQ(small.back(), 4);
  release_large_buffers();
}

#if defined(__SANITIZE_ADDRESS__)
// Under AddressSanitizer (scripts/sanitize.sh) a kept block and the rounding beyond the bytes asked
// for are poisoned: a use after deallocate_large or an overflow into the rounding is reported.
TEST(LargeBuffer, KeptBlocksAndRoundingArePoisonedUnderAddressSanitizer) {
  release_large_buffers();
  const std::size_t bytes = (std::size_t{3} << 20) + 5;  // a 4 MiB block
  char* p = static_cast<char*>(allocate_large(bytes));
  EXPECT_FALSE(__asan_address_is_poisoned(p));
  EXPECT_FALSE(__asan_address_is_poisoned(p + bytes - 1));
  EXPECT_TRUE(__asan_address_is_poisoned(p + bytes));
  EXPECT_TRUE(__asan_address_is_poisoned(p + (std::size_t{4} << 20) - 1));
  deallocate_large(p, bytes);
  EXPECT_TRUE(__asan_address_is_poisoned(p)) << "a kept block is not to be touched";
  const std::size_t fewer = bytes - 1000;
  char* q = static_cast<char*>(allocate_large(fewer));
  ASSERT_EQ(q, p) << "served from the kept block";
  EXPECT_FALSE(__asan_address_is_poisoned(q));
  EXPECT_FALSE(__asan_address_is_poisoned(q + fewer - 1));
  EXPECT_TRUE(__asan_address_is_poisoned(q + fewer));
  deallocate_large(q, fewer);
  release_large_buffers();
}
#endif

TEST(LargeBuffer, GrowsThroughReallocationKeepingItsElements) {
  LargeVector<int> v;
  for (int k = 0; k < 3'000'000; ++k) v.push_back(k);  // crosses the large-block threshold
  for (int k = 0; k < 3'000'000; k += 99'991) ASSERT_EQ(v[k], k);
}

TEST(ParallelSort, AgreesWithStdSort) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t n : {std::size_t{10}, std::size_t{50'000}, std::size_t{300'001}}) {
    std::vector<std::pair<double, int>> a(n);
    for (std::size_t k = 0; k < n; ++k) a[k] = {std::floor(u(rng) * 1000) / 1000, static_cast<int>(k)};  // ties in x
    auto b = a;
    std::sort(a.begin(), a.end());
    parallel_sort(b.begin(), b.end());
    EXPECT_TRUE(a == b) << "n = " << n;
  }
}

}  // namespace
}  // namespace covmap::voronoi
