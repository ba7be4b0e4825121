// Fuzz target: reported sensors as CSV (io/reported_sensors.h,
// parse_reported_sensors with SensorsFormat::kCsv); see sensors.h.
#include "sensors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  covmap::fuzz::fuzz_sensors(data, size, covmap::io::SensorsFormat::kCsv);
  return 0;
}
