// A long text rendered in pieces on several threads and handed on in order (internal to io/): the
// arc graph of a large diagram is tens of MB of text, whose formatting on one core would be a
// sizeable share of the engine's time.
//
// Contract:
//   - render(j, text) appends piece j to `text` (cleared before each call, its capacity kept); it
//     must depend on j alone, never on which thread runs it or on the other pieces, so the text
//     handed on is the same for every thread count.
//   - emit(piece) receives pieces 0, 1, …, count - 1 in that order, each exactly once, always on the
//     calling thread (so `emit` may write to a stream that is not thread-safe). While the next piece
//     to emit is not ready, the caller renders the next piece not taken yet, so one thread is as good
//     as no thread, and a piece is emitted while later ones are still being rendered.
//   - At most `window` pieces are held at a time (rendered and not yet emitted, or being rendered),
//     so memory stays at a few pieces whatever the length of the text.
//   - An exception thrown by render or emit stops the other threads after their current piece and
//     is rethrown to the caller; nothing more is emitted after it.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace covmap::io::detail {

struct OrderedPieces {
  int threads = 1;          // rendering threads, the caller's own included; 1: all on the caller
  std::size_t window = 8;   // pieces held at most (>= threads)
};

void render_pieces_in_order(std::size_t count, const OrderedPieces& options,
                            const std::function<void(std::size_t piece, std::string& text)>& render,
                            const std::function<void(std::string_view piece)>& emit);

// Threads for a text of about `bytes` bytes: 1 below kThreadedTextBytes, where starting a thread
// costs more than it saves; else the machine's cores, at most 4.
inline constexpr std::size_t kThreadedTextBytes = std::size_t{1} << 20;
int rendering_threads(std::size_t bytes);

}  // namespace covmap::io::detail
