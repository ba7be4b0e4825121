// Numbers for people: fixed notation, a precision that suits the size (never "(9.2005e-05 s)" or
// "position off by 2.51e+03 m").
#include "core/readable_numbers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace covmap {
namespace {

TEST(ReadableNumbers, MetresPickTheirUnitAndPrecision) {
  EXPECT_EQ(metres(2510.3), "2510 m");
  EXPECT_EQ(metres(12.34), "12.3 m");
  EXPECT_EQ(metres(0.0031), "3.1 mm");
  EXPECT_EQ(metres(25300), "25.3 km");
  EXPECT_EQ(metres(4e-5), "< 0.1 mm");
  EXPECT_EQ(metres(0), "0 m");
  EXPECT_EQ(metres(-150), "-150 m");
  EXPECT_EQ(metres(std::nan("")), "unknown");
}

TEST(ReadableNumbers, SecondsNeverUseExponents) {
  EXPECT_EQ(seconds(9.2005e-05), "< 0.001 s");
  EXPECT_EQ(seconds(0.4567), "0.457 s");
  EXPECT_EQ(seconds(83.24), "83.2 s");
  EXPECT_EQ(seconds(4000.4), "4000 s");
}

TEST(ReadableNumbers, NoTextHasAnExponentWhateverTheValue) {
  for (double v = 1e-30; v < 1e30; v *= 7.3) {
    for (const std::string& text : {metres(v), seconds(v), fixed(v, 3)}) {
      EXPECT_EQ(text.find('e'), std::string::npos) << v << " -> " << text;
    }
  }
  EXPECT_EQ(fixed(std::numeric_limits<double>::infinity(), 2), "infinite");
}

TEST(ReadableNumbers, Plurals) {
  EXPECT_EQ(plural(1, "site"), "1 site");
  EXPECT_EQ(plural(0, "site"), "0 sites");
  EXPECT_EQ(plural(58, "feature"), "58 features");
}

}  // namespace
}  // namespace covmap
