// Fuzz target: reported sensors as covmap.sites/1 (extended with lon/lat, powers and sigmas) (io/reported_sensors.h,
// parse_reported_sensors with SensorsFormat::kSitesJson); see sensors.h.
#include "sensors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  covmap::fuzz::fuzz_sensors(data, size, covmap::io::SensorsFormat::kSitesJson);
  return 0;
}
