#include "core/readable_numbers.h"

#include <cmath>
#include <cstdio>

namespace covmap {

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) return std::isnan(value) ? "unknown" : value > 0 ? "infinite" : "-infinite";
  char buffer[64];
  // Beyond 1e15 fixed notation only adds digits nobody reads; %.0f still prints them exactly.
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::fabs(value) < 1e18 ? value : std::copysign(1e18, value));
  return buffer;
}

std::string metres(double m) {
  if (!std::isfinite(m)) return fixed(m, 0);
  const double a = std::fabs(m);
  if (a >= 1e4) return fixed(m / 1000, 1) + " km";
  if (a >= 100) return fixed(m, 0) + " m";
  if (a >= 1) return fixed(m, 1) + " m";
  if (a >= 1e-4) return fixed(m * 1000, 1) + " mm";
  return a == 0 ? "0 m" : "< 0.1 mm";
}

std::string seconds(double s) {
  if (!std::isfinite(s)) return fixed(s, 0);
  if (s < 0.001) return "< 0.001 s";
  if (s < 10) return fixed(s, 3) + " s";
  if (s < 1000) return fixed(s, 1) + " s";
  return fixed(s, 0) + " s";
}

std::string plural(std::size_t n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace covmap
