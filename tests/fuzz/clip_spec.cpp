// Fuzz target: the --clip argument (io/polygon_io.h, parse_clip) as a rectangle spec.
//
// parse_clip reads the file when the spec names an existing path, and a fuzzer must not read
// whatever file its bytes happen to name ("/dev/zero" would hang it): such specs are skipped, by
// the same test parse_clip makes. The file's content is fuzzed by the polygon_json target.
#include <filesystem>
#include <string>
#include <system_error>

#include "checks.h"
#include "io/input_error.h"
#include "io/polygon_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace covmap;
  const std::string spec(fuzz::as_text(data, size));
  std::error_code ec;
  if (std::filesystem::exists(spec, ec)) return 0;
  try {
    fuzz::check_clip_polygon(io::parse_clip(spec), "clip rectangle");
  } catch (const io::InputError&) {
  }
  return 0;
}
