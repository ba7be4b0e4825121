// Numbers as people type them on a command line or in a request: one whole finite number, or
// nothing. "nan", "inf", "1e999", "3.5x" and "" are not numbers here, so an option's rule
// judges the text exactly as typed, before any conversion could turn it into something else.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace covmap {

// The finite double the whole text spells (strtod's syntax), or nullopt.
std::optional<double> parse_finite_number(std::string_view text);
// The integer the whole text spells in base 10, or nullopt (also when out of long long's range).
std::optional<long long> parse_whole_number(std::string_view text);

// The rules every option of this kind follows, in the words a person reads: empty when `text`
// passes, else "must be a positive number (got '0')", "must be a number ≥ 0 (got '-1')", "must be
// a whole number in 1–64 (got '65')".
std::string positive_number_problem(std::string_view text);
std::string non_negative_number_problem(std::string_view text);
std::string whole_number_problem(std::string_view text, long long lowest, long long highest);

}  // namespace covmap
