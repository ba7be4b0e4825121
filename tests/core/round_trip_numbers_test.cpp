// core/round_trip_numbers.h: every JSON token is a JSON float token that nlohmann and strtod (two readers
// independent of std::to_chars) read back to the same bits, and it is as short as the shortest
// round-trip text printf's %.Ng gives (the classic search over N).
#include "core/round_trip_numbers.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <stdexcept>

namespace covmap {
namespace {

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// printf's %.Ng with the fewest significant digits N that reads back to the same double.
std::string shortest_g(double v) {
  for (int digits = 1;; ++digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (same_bits(std::strtod(text, nullptr), v) || digits == 17) return text;
  }
}

// Significant digits of a number's text: its mantissa's digits without leading or trailing zeros
// ("0.00120" -> 2, "1200" -> 2).
int significant_digits(const std::string& text) {
  std::string digits;
  for (const char c : text.substr(0, text.find('e'))) if (c >= '0' && c <= '9') digits += c;
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return 1;
  return static_cast<int>(digits.find_last_not_of('0') - first + 1);
}

// The token is as short as the shortest %g text. Its significant digits are as few too, except
// where to_chars writes an integer above 2^53 in fixed notation: it then spells the exact integer
// (no shorter in characters), which printf's %.0f gives independently.
void expect_shortest(const std::string& token, double v) {
  const std::string own = token.ends_with(".0") ? token.substr(0, token.size() - 2) : token;
  const std::string g = shortest_g(v);
  EXPECT_LE(own.size(), g.size()) << token << " vs " << g;
  if (significant_digits(own) == significant_digits(g)) return;
  char exact[400];
  std::snprintf(exact, sizeof exact, "%.0f", v);
  EXPECT_TRUE(std::fabs(v) > 0x1p53 && own == exact) << token << " vs " << g;
}

void expect_token_round_trips(double v) {
  const std::string token = [&] { std::string s; append_json_number(s, v); return s; }();
  // The JSON number grammar (RFC 8259), and always a float token (a fraction or an exponent).
  static const std::regex kJsonNumber(R"(-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
  EXPECT_TRUE(std::regex_match(token, kJsonNumber)) << token;
  EXPECT_NE(token.find_first_of(".e"), std::string::npos) << token;
  const nlohmann::json parsed = nlohmann::json::parse(token);
  EXPECT_TRUE(parsed.is_number_float()) << token;
  EXPECT_TRUE(same_bits(parsed.get<double>(), v)) << token << " for " << std::hexfloat << v;
  EXPECT_TRUE(same_bits(std::strtod(token.c_str(), nullptr), v)) << token;
  expect_shortest(token, v);
}

TEST(JsonNumber, HardDoublesRoundTripBitExactly) {
  const double hard[] = {
      0.0, -0.0, 1.0, -1.0, 10.0, 0.1, 0.1 + 0.2, 1.0 / 3.0, 2.0 / 3.0, std::nextafter(1.0, 2.0),
      std::nextafter(1.0, 0.0), DBL_MAX, -DBL_MAX, DBL_MIN, -DBL_MIN, DBL_TRUE_MIN, -DBL_TRUE_MIN,
      std::nextafter(DBL_MIN, 0.0),  // the largest subnormal
      2.2250738585072011e-308, 4.9406564584124654e-324, 1e-300, 1e300, 1e308,
      // Around 1e15..1e17, where to_chars switches between fixed and scientific and where doubles
      // stop holding every integer (2^53).
      1e15, 1e15 + 0.5, 999999999999999.9, 1e16, 1e16 - 2, 1e16 + 2, 1e17, 1e17 - 16, 9007199254740992.0,
      9007199254740994.0, 9007199254740991.0, 123456789012345680000.0, 9223372036854775808.0,
      18446744073709551616.0, 1e21, 1e22, 1e23, 5e-324, 123456789.123456789, -7.25, 0.30000000000000004,
      4503599627370496.5, 0.000001, 0.0000001, 1234567.0, 100.0, -1e-7};
  for (const double v : hard) expect_token_round_trips(v);
}

TEST(JsonNumber, RandomBitPatternsRoundTrip) {
  std::mt19937_64 random(16);
  for (int i = 0; i < 20000; ++i) {
    const double v = std::bit_cast<double>(random());
    if (std::isfinite(v)) expect_token_round_trips(v);
  }
  // And ordinary magnitudes, where fixed notation and the ".0" rule are common.
  std::uniform_real_distribution<double> coordinate(-1e7, 1e7);
  for (int i = 0; i < 20000; ++i) {
    expect_token_round_trips(coordinate(random));
    expect_token_round_trips(std::round(coordinate(random)));
  }
}

TEST(JsonNumber, IntegralValuesAreFloatTokensAndNegativeZeroKeepsItsSign) {
  std::string s;
  append_json_number(s, 10.0);
  EXPECT_EQ(s, "10.0");
  s.clear();
  append_json_number(s, -0.0);
  EXPECT_EQ(s, "-0.0");
  EXPECT_TRUE(std::signbit(nlohmann::json::parse(s).get<double>()));
  s.clear();
  append_json_number(s, 1e16);
  EXPECT_EQ(s, "1e+16");
}

TEST(JsonNumber, NonFiniteIsAPreconditionViolation) {
  std::string s;
  EXPECT_THROW(append_json_number(s, std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(append_json_number(s, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace covmap
