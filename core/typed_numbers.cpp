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

std::string positive_number_problem(std::string_view text) {
  const std::optional<double> v = parse_finite_number(text);
  return v && *v > 0 ? "" : "must be a positive number (got '" + std::string(text) + "')";
}

std::string non_negative_number_problem(std::string_view text) {
  const std::optional<double> v = parse_finite_number(text);
  return v && *v >= 0 ? "" : "must be a number ≥ 0 (got '" + std::string(text) + "')";
}

std::string whole_number_problem(std::string_view text, long long lowest, long long highest) {
  const std::optional<long long> v = parse_whole_number(text);
  if (v && *v >= lowest && *v <= highest) return "";
  return "must be a whole number in " + std::to_string(lowest) + "–" + std::to_string(highest) + " (got '" +
         std::string(text) + "')";
}

}  // namespace covmap
