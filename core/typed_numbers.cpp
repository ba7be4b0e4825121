#include "core/typed_numbers.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace covmap {

std::optional<double> parse_finite_number(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const std::string s(text);  // strtod needs the terminating zero
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(s.c_str(), &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<long long> parse_whole_number(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const std::string s(text);
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(s.c_str(), &end, 10);
  if (*end != '\0' || errno == ERANGE) return std::nullopt;
  return value;
}

}  // namespace covmap
