// The arc graph writer's pieces and length bound (internal to io/; write_diagram_json and
// diagram_json_text are built on them, tests/io checks them).
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

#include "core/diagram.h"

namespace covmap::io::detail {

// At least the length of the covmap.arcgraph/1 text of `d` as written by write_diagram_json: every
// number and index counted at its longest, every string character as a six-byte escape.
std::size_t diagram_json_size_bound(const Diagram& d);

// How the text is cut and rendered. The text does not depend on either setting.
struct DiagramTextPieces {
  // Each array's elements go in pieces of about this many bytes of their length bound (at least one
  // element each): small enough that a piece is written while the next ones are rendered, large
  // enough that handing pieces between threads costs nothing next to formatting them.
  std::size_t piece_bytes = std::size_t{1} << 17;
  int threads = 0;  // rendering threads; 0: rendering_threads(the length bound) (ordered_pieces.h)
};

// The covmap.arcgraph/1 text of `d`, handed to `emit` piece by piece in order, always on the calling
// thread. The caller has checked that `d` can be written (finite numbers, UTF-8 strings).
void render_diagram_json(const Diagram& d, const DiagramTextPieces& options,
                         const std::function<void(std::string_view)>& emit);

}  // namespace covmap::io::detail
