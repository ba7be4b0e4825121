// The three reported-sensor targets (sensors_json, sensors_csv, sensors_geojson): one syntax each,
// every input read twice, once for a lon/lat map (with its projection and --alpha, so powers become
// weights) and once for a planar map (--planar, no alpha), as `covmap audit` can.
#pragma once

#include <cstddef>
#include <cstdint>

#include "checks.h"
#include "io/input_error.h"
#include "io/local_projection.h"
#include "io/reported_sensors.h"

namespace covmap::fuzz {

inline void fuzz_sensors(const std::uint8_t* data, std::size_t size, io::SensorsFormat format) {
  static const io::LocalProjection projection = io::LocalProjection::about(8.0, 47.0);
  io::ReportedSensorOptions geographic;
  geographic.alpha = 3.5;
  geographic.frame = &projection;
  io::ReportedSensorOptions planar;
  planar.planar = true;
  for (const auto& options : {geographic, planar}) {
    try {
      check_sensors(io::parse_reported_sensors(as_text(data, size), "fuzz", options, format), options.frame != nullptr);
    } catch (const io::InputError&) {
    }
  }
}

}  // namespace covmap::fuzz
