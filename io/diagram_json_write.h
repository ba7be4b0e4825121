// The arc graph writer's length bound (internal to io/; diagram_json_text reserves it).
#pragma once

#include <cstddef>

#include "core/diagram.h"

namespace covmap::io::detail {

// At least the length of the covmap.arcgraph/1 text of `d` as written by write_diagram_json: every
// number and index counted at its longest, every string character as a six-byte escape.
std::size_t diagram_json_size_bound(const Diagram& d);

}  // namespace covmap::io::detail
