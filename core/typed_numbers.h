// Numbers as people type them on a command line or in a request: one whole finite number, or
// nothing. "nan", "inf", "1e999", "3.5x" and "" are not numbers here, so an option's rule
// judges the text exactly as typed, before any conversion could turn it into something else.
#pragma once

#include <optional>
#include <string_view>

namespace covmap {

// The finite double the whole text spells (strtod's syntax), or nullopt.
std::optional<double> parse_finite_number(std::string_view text);
// The integer the whole text spells in base 10, or nullopt (also when out of long long's range).
std::optional<long long> parse_whole_number(std::string_view text);

}  // namespace covmap
