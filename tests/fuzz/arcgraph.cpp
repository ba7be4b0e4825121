// Fuzz target: the covmap.arcgraph/1 reader (io/diagram_json.h), every input in both label modes:
// kRequired (a diagram: sites, labels, faces) and kIgnored (the unlabelled graphs of recognize and
// compare).
#include "checks.h"
#include "io/diagram_json.h"
#include "io/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace covmap;
  for (const io::ArcLabels labels : {io::ArcLabels::kRequired, io::ArcLabels::kIgnored}) {
    try {
      fuzz::check_diagram(io::parse_diagram_json(fuzz::as_text(data, size), "fuzz.json", labels), labels);
    } catch (const io::InputError&) {
    }
  }
  return 0;
}
