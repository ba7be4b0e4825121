#include "core/round_trip_numbers.h"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace covmap {

std::string round_trip_number(double value) {
  // std::to_chars without a precision gives the shortest round-trip representation.
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

char* write_json_number(double value, char* out) {
  if (!std::isfinite(value)) throw std::invalid_argument("write_json_number: JSON has no NaN or infinity");
  // Without a format argument, to_chars picks the shorter of fixed and scientific notation and the
  // fewest digits that round-trip.
  const auto [end, error] = std::to_chars(out, out + kMaxJsonNumberChars - 2, value);
  if (error != std::errc()) throw std::logic_error("write_json_number: kMaxJsonNumberChars is too small");
  // A plain loop: find_first_of(".e") calls memchr on the two-character set once per character.
  for (const char* c = out; c != end; ++c) {
    if (*c == '.' || *c == 'e') return end;
  }
  end[0] = '.';
  end[1] = '0';
  return end + 2;
}

void append_json_number(std::string& out, double value) {
  char buffer[kMaxJsonNumberChars];
  out.append(buffer, write_json_number(value, buffer));
}

}  // namespace covmap
