#include "tools/mapgen/reported_sensors.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace covmap::mapgen {
namespace {

bool fail(std::string* why, const std::string& message) {
  if (why) *why = message;
  return false;
}

bool finite_non_negative(double v) { return std::isfinite(v) && v >= 0.0; }

}  // namespace

bool ReportErrorOptions::is_valid(std::string* why) const {
  if (!finite_non_negative(position_sigma_m)) return fail(why, "position sigma must be finite and >= 0");
  if (!finite_non_negative(power_sigma_db)) return fail(why, "power sigma must be finite and >= 0");
  if (!(gross_fraction >= 0.0 && gross_fraction <= 1.0)) return fail(why, "gross fraction must be in [0, 1]");
  if (!finite_non_negative(gross_position_min_m) || !std::isfinite(gross_position_max_m) ||
      gross_position_max_m < gross_position_min_m)
    return fail(why, "gross position offsets need 0 <= min <= max (finite)");
  if (!finite_non_negative(gross_power_min_db) || !std::isfinite(gross_power_max_db) ||
      gross_power_max_db < gross_power_min_db)
    return fail(why, "gross power offsets need 0 <= min <= max (finite)");
  return true;
}

std::string_view to_string(GrossErrorKind kind) {
  switch (kind) {
    case GrossErrorKind::kNone: return "none";
    case GrossErrorKind::kPosition: return "position";
    case GrossErrorKind::kPower: return "power";
    case GrossErrorKind::kBoth: return "both";
  }
  return "none";
}

std::size_t gross_error_count(std::size_t n, double gross_fraction) {
  return static_cast<std::size_t>(std::llround(gross_fraction * static_cast<double>(n)));
}

std::vector<SensorError> draw_sensor_errors(std::size_t n, const ReportErrorOptions& options, RandomStream& random) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument("reported-sensor errors: " + why);
  std::vector<SensorError> errors(n);
  // Which sensors are gross: the first `count` of a partial Fisher–Yates shuffle.
  const std::size_t count = std::min(n, gross_error_count(n, options.gross_fraction));
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  for (std::size_t k = 0; k < count; ++k) std::swap(order[k], order[k + random.below(n - k)]);
  for (std::size_t k = 0; k < count; ++k) {
    constexpr GrossErrorKind kinds[3] = {GrossErrorKind::kPosition, GrossErrorKind::kPower, GrossErrorKind::kBoth};
    errors[order[k]].gross = kinds[random.below(3)];
  }
  for (auto& e : errors) {
    e.position_noise = {options.position_sigma_m * random.normal(), options.position_sigma_m * random.normal()};
    e.power_noise_db = options.power_sigma_db * random.normal();
    if (e.gross == GrossErrorKind::kPosition || e.gross == GrossErrorKind::kBoth) {
      const double distance = random.uniform(options.gross_position_min_m, options.gross_position_max_m);
      const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
      e.gross_offset = {distance * std::cos(angle), distance * std::sin(angle)};
    }
    if (e.gross == GrossErrorKind::kPower || e.gross == GrossErrorKind::kBoth) {
      const double size = random.uniform(options.gross_power_min_db, options.gross_power_max_db);
      e.gross_power_db = random.below(2) == 0 ? size : -size;
    }
  }
  return errors;
}

}  // namespace covmap::mapgen
