// The exact orientation predicate against integer arithmetic: coordinates that are integers times
// a power of two are exact doubles, and their determinant is exact in 128-bit integers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "core/diagram.h"
#include "core/orientation.h"

namespace covmap {
namespace {

int exact_sign(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx,
               std::int64_t cy) {
  const __int128 det = static_cast<__int128>(bx - ax) * (cy - ay) - static_cast<__int128>(by - ay) * (cx - ax);
  return (det > 0) - (det < 0);
}

TEST(Orientation, MatchesIntegerArithmeticOnRandomAndNearlyCollinearPoints) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t{1} << 40), std::int64_t{1} << 40);
  std::uniform_int_distribution<int> nudge(-1, 1);
  int collinear = 0, nearly = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::int64_t ax = coord(rng), ay = coord(rng);
    std::int64_t bx = coord(rng), by = coord(rng);
    std::int64_t cx = coord(rng), cy = coord(rng);
    if (trial % 2 == 1) {  // on the line a + k (b - a), give or take one unit: the filter's hard cases
      const std::int64_t k = trial % 7 - 3;
      cx = ax + k * ((bx - ax) / 4) + nudge(rng), cy = ay + k * ((by - ay) / 4) + nudge(rng);
      bx = ax + 4 * ((bx - ax) / 4), by = ay + 4 * ((by - ay) / 4);
      ++nearly;
    }
    // Also at the ends of the double range, where products overflow or underflow (fuzzing found a
    // ring at ±1e308 read as clockwise and a square of side 1e-162 read as collinear).
    for (const double scale : {1.0, 0x1p-60, 0x1p+60, 0x1p+980, 0x1p-1000}) {
      const Point a{static_cast<double>(ax) * scale, static_cast<double>(ay) * scale};
      const Point b{static_cast<double>(bx) * scale, static_cast<double>(by) * scale};
      const Point c{static_cast<double>(cx) * scale, static_cast<double>(cy) * scale};
      const int want = exact_sign(ax, ay, bx, by, cx, cy);
      ASSERT_EQ(orientation(a, b, c), want) << "trial " << trial << " scale " << scale;
      collinear += want == 0;
    }
  }
  EXPECT_GT(collinear, 1000);  // the battery really exercised exact zeros
  EXPECT_EQ(nearly, 10000);
}

TEST(Orientation, SignsOfTheThreeTurns) {
  EXPECT_EQ(orientation({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(orientation({0, 0}, {0, 1}, {1, 0}), -1);
  EXPECT_EQ(orientation({0, 0}, {1, 1}, {2, 2}), 0);
}

}  // namespace
}  // namespace covmap
