// Fuzz target: clip polygon files, covmap.polygon/1 and GeoJSON (io/polygon_io.h,
// parse_polygon_json).
#include <string>

#include "checks.h"
#include "io/input_error.h"
#include "io/polygon_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace covmap;
  try {
    fuzz::check_clip_polygon(io::parse_polygon_json(std::string(fuzz::as_text(data, size)), "fuzz.json"), "clip polygon");
  } catch (const io::InputError&) {
  }
  return 0;
}
