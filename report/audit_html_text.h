// Text for report.html (internal to io/): escaping of input strings and numbers for people.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace covmap::report::detail {

// Text safe in HTML content and in double- or single-quoted attribute values: & < > " ' become
// entities; control characters other than tab, newline and carriage return, and bytes that are
// not part of valid UTF-8, become U+FFFD (HTML forbids the former; the latter would garble
// what follows in some browsers).
std::string html_escape(std::string_view text);

// A number for people: `significant` significant digits in fixed notation ("12.3", "2510",
// "0.00123"); below 10⁻³ and from 10¹⁵ as printf's %g writes them ("0.000123", "1.5e-07"); an en
// dash for NaN, infinity or nullopt.
std::string human_number(double value, int significant = 3);
std::string human_number(const std::optional<double>& value, int significant = 3);

// A number with a fixed count of decimals ("12.35"); an en dash when not finite.
std::string fixed_number(double value, int decimals);

// The value of a sortable table cell: the shortest round-trip text of a finite number, empty for
// NaN, infinity or nullopt (sorted last).
std::string sort_key(const std::optional<double>& value);

}  // namespace covmap::report::detail
