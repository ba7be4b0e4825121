// Numbers as typed: what strtod/strtoll would take of the whole text, finite and in range, and
// nothing else.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "core/typed_numbers.h"

namespace covmap {
namespace {

TEST(TypedNumbers, FiniteNumbersAreTakenWhole) {
  EXPECT_EQ(parse_finite_number("3.5"), 3.5);
  EXPECT_EQ(parse_finite_number("-0.25"), -0.25);
  EXPECT_EQ(parse_finite_number("1e-300"), 1e-300);
  EXPECT_EQ(parse_finite_number("1.7976931348623157e308"), std::numeric_limits<double>::max());
  for (const char* bad : {"", "nan", "NaN", "inf", "-inf", "1e999", "3.5x", "x3", "3,5", "0x"})
    EXPECT_FALSE(parse_finite_number(bad)) << bad;
  // Only the view is read, not what follows it in memory.
  const std::string text = "12345";
  EXPECT_EQ(parse_finite_number(std::string_view(text).substr(0, 2)), 12.0);
}

TEST(TypedNumbers, WholeNumbersAreTakenWholeAndInRange) {
  EXPECT_EQ(parse_whole_number("0"), 0);
  EXPECT_EQ(parse_whole_number("-64"), -64);
  EXPECT_EQ(parse_whole_number("9223372036854775807"), std::numeric_limits<long long>::max());
  for (const char* bad : {"", "2.5", "1e3", "9223372036854775808", "12a", "0x10"})
    EXPECT_FALSE(parse_whole_number(bad)) << bad;
}

TEST(TypedNumbers, RulesSayWhatIsWrongWithTheTextAsTyped) {
  EXPECT_EQ(positive_number_problem("3.5"), "");
  EXPECT_EQ(positive_number_problem("0"), "must be a positive number (got '0')");
  EXPECT_EQ(positive_number_problem("nan"), "must be a positive number (got 'nan')");
  EXPECT_EQ(non_negative_number_problem("0"), "");
  EXPECT_EQ(non_negative_number_problem("-1e-9"), "must be a number ≥ 0 (got '-1e-9')");
  EXPECT_EQ(whole_number_problem("64", 1, 64), "");
  EXPECT_EQ(whole_number_problem("65", 1, 64), "must be a whole number in 1–64 (got '65')");
  EXPECT_EQ(whole_number_problem("1.5", 1, 64), "must be a whole number in 1–64 (got '1.5')");
}

}  // namespace
}  // namespace covmap
