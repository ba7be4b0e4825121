// covmap::mapgen reported-sensor errors: how an operator's sensor list differs from the truth.
//
// Model (each sensor independently, plus a fixed number of gross errors):
//  - small errors: each coordinate of the position gets N(0, position_sigma_m²) metres, the
//    transmit power N(0, power_sigma_db²) dB;
//  - gross errors: exactly round(gross_fraction × n) sensors, a uniformly random subset, get one of
//    {position, power, both} with equal probability, on top of the small errors. A gross position
//    error moves the sensor by a distance uniform in [gross_position_min_m, gross_position_max_m]
//    in a uniformly random direction; a gross power error adds ± (uniform in [gross_power_min_db,
//    gross_power_max_db]) dB, either sign with equal probability.
// draw_sensor_errors is deterministic for a given stream state; options are checked by
// ReportErrorOptions::is_valid (draw_sensor_errors throws std::invalid_argument when invalid).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "tools/mapgen/random_stream.h"
#include "core/diagram.h"

namespace covmap::mapgen {

struct ReportErrorOptions {
  double position_sigma_m = 20.0;       // standard deviation of each coordinate's small error
  double power_sigma_db = 1.0;          // standard deviation of the small transmit-power error
  double gross_fraction = 0.0;          // share of sensors with a gross error, in [0, 1]
  double gross_position_min_m = 1000.0; // a gross position error moves a sensor at least this far
  double gross_position_max_m = 3000.0; // ... and at most this far
  double gross_power_min_db = 6.0;      // a gross power error is at least this large (either sign)
  double gross_power_max_db = 12.0;     // ... and at most this large

  // False, with the reason in *why (when given), for negative sigmas, a fraction outside [0, 1],
  // or a range with min < 0 or max < min.
  bool is_valid(std::string* why) const;
};

enum class GrossErrorKind { kNone, kPosition, kPower, kBoth };

// "none", "position", "power", "both".
std::string_view to_string(GrossErrorKind kind);

struct SensorError {
  Point position_noise;  // small error, metres
  double power_noise_db = 0.0;    // small error, dB
  GrossErrorKind gross = GrossErrorKind::kNone;
  Point gross_offset;    // metres; zero unless gross is kPosition or kBoth
  double gross_power_db = 0.0;    // zero unless gross is kPower or kBoth

  Point total_offset() const { return {position_noise.x + gross_offset.x, position_noise.y + gross_offset.y}; }
  double total_power_db() const { return power_noise_db + gross_power_db; }
};

// The number of gross errors for n sensors: round(gross_fraction × n), halves away from zero.
std::size_t gross_error_count(std::size_t n, double gross_fraction);

std::vector<SensorError> draw_sensor_errors(std::size_t n, const ReportErrorOptions& options, RandomStream& random);

}  // namespace covmap::mapgen
