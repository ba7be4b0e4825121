// Site colours for every picture (svg.h: site_colour_for): a hue from the site's id, not its index.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "report/svg.h"
#include "report/svg_layout.h"

namespace covmap::report {
namespace {

// 2^64 x (1 - 1/phi): n times this, modulo 2^64, is n golden angles as a fraction of a full turn,
// exactly (fixed point), so consecutive integers step round the colour wheel by 137.5 degrees.
constexpr std::uint64_t kGoldenTurn = 0x61C8864680B583EBull;

// Lightness and saturation: light for faces (labels and arcs stay readable on them), dark for dots.
constexpr double kFaceSaturation = 0.55, kFaceLightness = 0.80;
constexpr double kDotSaturation = 0.6, kDotLightness = 0.35;

std::string hex_colour(double hue_degrees, double saturation, double lightness) {
  // HSL to RGB (CSS Color 3 algorithm); hex because SVG 1.1 viewers need not understand hsl().
  const auto channel = [&](double n) {
    const double k = std::fmod(n + hue_degrees / 30.0, 12.0);
    const double a = saturation * std::min(lightness, 1 - lightness);
    return lightness - a * std::max(-1.0, std::min({k - 3, 9 - k, 1.0}));
  };
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", static_cast<int>(std::lround(channel(0) * 255)),
                static_cast<int>(std::lround(channel(8) * 255)), static_cast<int>(std::lround(channel(4) * 255)));
  return buffer;
}

// The id as an integer when it is one in canonical decimal form ("17", "-3"; not "017", "+3", "1e3").
std::optional<std::int64_t> canonical_integer(std::string_view id) {
  const std::string_view digits = !id.empty() && id.front() == '-' ? id.substr(1) : id;
  if (digits.empty() || (digits.size() > 1 && digits.front() == '0') || (digits == "0" && digits.size() != id.size()))
    return std::nullopt;
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(id.data(), id.data() + id.size(), value);
  if (ec != std::errc() || end != id.data() + id.size()) return std::nullopt;
  return value;
}

// FNV-1a: a fixed, platform-independent hash of the id's bytes (std::hash may differ between builds).
std::uint64_t text_hash(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const unsigned char c : text) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

double hue_of(std::uint64_t n) {
  const std::uint64_t turn = n * kGoldenTurn;  // wraps modulo 2^64 by design
  return static_cast<double>(turn >> 11) * 0x1p-53 * 360.0;
}

double hue_for(std::string_view id) {
  if (const auto n = canonical_integer(id)) return hue_of(static_cast<std::uint64_t>(*n));
  return hue_of(text_hash(id));
}

}  // namespace

std::string site_colour_for(std::string_view id) { return hex_colour(hue_for(id), kFaceSaturation, kFaceLightness); }

std::string site_colour(std::size_t i) { return hex_colour(hue_of(i), kFaceSaturation, kFaceLightness); }

namespace detail {

std::string site_dot_colour_for(std::string_view id) { return hex_colour(hue_for(id), kDotSaturation, kDotLightness); }

}  // namespace detail
}  // namespace covmap::report
