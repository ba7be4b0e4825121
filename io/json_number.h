// covmap::io JSON number tokens: a finite double as the shortest JSON text that reads back to the
// same bits (used by every covmap.arcgraph/1 and covmap.sites/1 writer).
//
// Contract:
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

namespace covmap::io {

// Room for the longest token: "-2.2250738585072014e-308" is 24 characters; 32 leaves a margin.
inline constexpr std::size_t kMaxJsonNumberChars = 32;

// Writes the token at `out` (which has kMaxJsonNumberChars bytes of room) and returns its end.
char* write_json_number(double value, char* out);

// Appends the token to `out`.
void append_json_number(std::string& out, double value);

}  // namespace covmap::io
