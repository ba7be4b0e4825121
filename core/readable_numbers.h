// Numbers for people: lengths and durations in fixed notation with a precision that suits their
// size, never "2.51e+03 m" or "9.2005e-05 s". Used by every message, progress line and report
// sentence covmap prints; files keep full precision (their writers do not use these).
//
//   metres(2510.3) == "2510 m"    metres(12.34) == "12.3 m"    metres(0.0031) == "3.1 mm"
//   metres(25300) == "25.3 km"    metres(4e-5) == "< 0.1 mm"   metres(NaN) == "unknown"
//   seconds(9.2e-5) == "< 0.001 s"  seconds(0.4567) == "0.457 s"  seconds(83.2) == "83.2 s"
//   count(58) == "58", plural(1, "site") == "1 site", plural(3, "site") == "3 sites"
#pragma once

#include <cstddef>
#include <string>

namespace covmap {

std::string metres(double m);
std::string seconds(double s);
// A dimensionless number in fixed notation with `decimals` places ("0.0012" for 1.2e-3, 4).
std::string fixed(double value, int decimals);
std::string plural(std::size_t n, const std::string& noun);

}  // namespace covmap
