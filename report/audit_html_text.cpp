#include "report/audit_html_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/round_trip_numbers.h"

namespace covmap::report::detail {
namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD
constexpr std::string_view kDash = "\xE2\x80\x93";          // U+2013, "no value"

bool continuation(std::string_view text, std::size_t i, unsigned char lo = 0x80, unsigned char hi = 0xBF) {
  if (i >= text.size()) return false;
  const auto c = static_cast<unsigned char>(text[i]);
  return c >= lo && c <= hi;
}

// Length of the valid UTF-8 sequence starting at text[i] (a byte >= 0x80), 0 if it is not one.
// Overlong forms, surrogates and code points above U+10FFFF are invalid (RFC 3629, table 3-7 of
// the Unicode standard).
std::size_t utf8_sequence(std::string_view text, std::size_t i) {
  const auto c = static_cast<unsigned char>(text[i]);
  if (c >= 0xC2 && c <= 0xDF) return continuation(text, i + 1) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    const unsigned char lo = c == 0xE0 ? 0xA0 : 0x80;
    const unsigned char hi = c == 0xED ? 0x9F : 0xBF;
    return continuation(text, i + 1, lo, hi) && continuation(text, i + 2) ? 3 : 0;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    const unsigned char lo = c == 0xF0 ? 0x90 : 0x80;
    const unsigned char hi = c == 0xF4 ? 0x8F : 0xBF;
    return continuation(text, i + 1, lo, hi) && continuation(text, i + 2) && continuation(text, i + 3) ? 4 : 0;
  }
  return 0;
}

}  // namespace

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      const std::size_t n = utf8_sequence(text, i);
      if (n == 0) {
        out += kReplacement;
        ++i;
      } else {
        out.append(text.substr(i, n));
        i += n;
      }
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F) out += kReplacement;
        else out += static_cast<char>(c);
    }
    ++i;
  }
  return out;
}

std::string human_number(double value, int significant) {
  if (!std::isfinite(value)) return std::string(kDash);
  char buffer[40];
  // Fixed notation with `significant` digits for what people read (2 510 m, not 2.51e+03 m); the
  // exponent form only for the very small and the very large, where it says more in less space.
  const double magnitude = std::abs(value);
  if (magnitude == 0.0) return "0";
  if (magnitude >= 1e-3 && magnitude < 1e15) {
    const int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    const int decimals = std::max(0, significant - 1 - exponent);
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
  }
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  return buffer;
}

std::string human_number(const std::optional<double>& value, int significant) {
  return value ? human_number(*value, significant) : std::string(kDash);
}

std::string fixed_number(double value, int decimals) {
  if (!std::isfinite(value)) return std::string(kDash);
  // %f writes every integer digit; beyond 15 of them the exponent form says more, in less space.
  if (std::abs(value) >= 1e15) return human_number(value, 6);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string sort_key(const std::optional<double>& value) {
  return value && std::isfinite(*value) ? round_trip_number(*value) : std::string();
}

}  // namespace covmap::report::detail
