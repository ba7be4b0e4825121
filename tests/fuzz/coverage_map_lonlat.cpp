// Fuzz target: GeoJSON coverage maps (io/coverage_map.h, parse_coverage_map) with
// [lon, lat] positions, projected.
#include "checks.h"
#include "io/coverage_map.h"
#include "io/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace covmap;
  io::CoverageMapOptions options;
  options.planar = false;
  try {
    fuzz::check_coverage_map(io::parse_coverage_map(fuzz::as_text(data, size), "fuzz.geojson", options), options.planar);
  } catch (const io::InputError&) {
  }
  return 0;
}
