// Fuzz target: reported sensors as GeoJSON Points (io/reported_sensors.h,
// parse_reported_sensors with SensorsFormat::kGeoJson); see sensors.h.
#include "sensors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  covmap::fuzz::fuzz_sensors(data, size, covmap::io::SensorsFormat::kGeoJson);
  return 0;
}
