// Numbers for programs: a double as the shortest text that reads back to the same bits, plain
// (round_trip_number, for messages and text formats) or as a JSON number token (used by every
// covmap.arcgraph/1 and covmap.sites/1 writer and by the GeoJSON of the reports). Beside
// core/readable_numbers.h, which writes numbers for people.
//
// round_trip_number: std::to_chars's shortest round-trip form of any double, non-finite ones too
// ("0.1", "-1", "1e+300", "nan", "inf").
//
// JSON number tokens (write_json_number, append_json_number):
//   - The value must be finite (JSON has no NaN or infinity); callers check first and name the
//     path in their own error. A non-finite value is a precondition violation (std::invalid_argument).
//   - The text is std::to_chars's shortest round-trip form, so any correctly rounding reader
//     (strtod, std::from_chars, nlohmann, Python's json) gets back the identical double.
//   - It is always a JSON float token: when the shortest form has neither '.' nor an exponent
//     ("10", "-0", "123456789012345680000"), ".0" is appended. Why: a bare integer token is read as an
//     integer by JSON libraries that keep the distinction, and "-0" would come back as integer 0,
//     losing the sign of negative zero; "-0.0" keeps it. Exponent forms keep to_chars's spelling
//     ("1e+16", "5e-324"), which the JSON grammar allows.
#pragma once

#include <cstddef>
#include <string>

namespace covmap {

// Shortest text that reads back as the same double ("0.1", "-1", "1e+300", "nan", "inf").
std::string round_trip_number(double value);

// Room for the longest token: "-2.2250738585072014e-308" is 24 characters; 32 leaves a margin.
inline constexpr std::size_t kMaxJsonNumberChars = 32;

// Writes the token at `out` (which has kMaxJsonNumberChars bytes of room) and returns its end.
char* write_json_number(double value, char* out);

// Appends the token to `out`.
void append_json_number(std::string& out, double value);

}  // namespace covmap
