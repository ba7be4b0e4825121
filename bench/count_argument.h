// A whole count given on a benchmark's command line ("1e6" allowed), for the benchmarks whose --n
// takes a list of sizes.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace covmap::bench {

// text as a whole number in [minimum, 1e9]; otherwise CLI::ValidationError for `option`, saying
// that text is not `what`.
inline std::size_t parse_count(const std::string& text, double minimum, const std::string& option,
                               const std::string& what) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value >= minimum) || value > 1e9 || value != std::floor(value))
    throw CLI::ValidationError(option, "'" + text + "' is not " + what);
  return static_cast<std::size_t>(value);
}

}  // namespace covmap::bench
