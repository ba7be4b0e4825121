#include "io/ordered_pieces.h"

#include "core/parallel.h"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace covmap::io::detail {
namespace {

// The pieces between the threads. Piece j lives in slot j % window from when it is taken until it
// is emitted; it may be taken only once piece j - window has been emitted, so no two pieces in
// flight share a slot.
class Pieces {
 public:
  Pieces(std::size_t count, std::size_t window,
         const std::function<void(std::size_t, std::string&)>& render)
      : count_(count), window_(window), slots_(window), render_(render) {}

  // A helper thread: renders the next piece not taken, while there is room, until none is left.
  void help() {
    std::unique_lock lock(mutex_);
    for (;;) {
      changed_.wait(lock, [&] { return stop_ || next_ >= count_ || has_room(); });
      if (stop_ || next_ >= count_) return;
      if (!render_next(lock)) return;
    }
  }

  // The calling thread: emits every piece in order, rendering whatever is not taken yet while the
  // next one to emit is not ready.
  void run(const std::function<void(std::string_view)>& emit) {
    std::unique_lock lock(mutex_);
    while (emitted_ < count_) {
      Slot& slot = slots_[emitted_ % window_];
      if (slot.ready) {
        lock.unlock();
        try {
          emit(slot.text);
        } catch (...) {
          lock.lock();
          fail(std::current_exception());
          break;
        }
        lock.lock();
        slot.ready = false;
        ++emitted_;
        changed_.notify_all();
      } else if (next_ < count_ && has_room()) {
        if (!render_next(lock)) break;
      } else {
        changed_.wait(lock, [&] { return stop_ || slot.ready; });
        if (stop_) break;
      }
    }
    stop_ = true;
    changed_.notify_all();
  }

  void rethrow_failure() {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  struct Slot {
    std::string text;
    bool ready = false;
  };

  bool has_room() const { return next_ < emitted_ + window_; }

  // Takes piece next_ and renders it with the lock released; false if rendering threw.
  bool render_next(std::unique_lock<std::mutex>& lock) {
    const std::size_t j = next_++;
    Slot& slot = slots_[j % window_];
    lock.unlock();
    try {
      slot.text.clear();
      render_(j, slot.text);
    } catch (...) {
      lock.lock();
      fail(std::current_exception());
      return false;
    }
    lock.lock();
    slot.ready = true;
    changed_.notify_all();
    return true;
  }

  void fail(std::exception_ptr e) {
    if (!failure_) failure_ = std::move(e);
    stop_ = true;
    changed_.notify_all();
  }

  const std::size_t count_, window_;
  std::vector<Slot> slots_;
  const std::function<void(std::size_t, std::string&)>& render_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::size_t next_ = 0;     // the first piece not taken
  std::size_t emitted_ = 0;  // pieces handed on
  bool stop_ = false;
  std::exception_ptr failure_;
};

}  // namespace

void render_pieces_in_order(std::size_t count, const OrderedPieces& options,
                            const std::function<void(std::size_t, std::string&)>& render,
                            const std::function<void(std::string_view)>& emit) {
  const int threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(options.threads, 1)), count));
  if (threads <= 1) {
    std::string text;
    for (std::size_t j = 0; j < count; ++j) {
      text.clear();
      render(j, text);
      emit(text);
    }
    return;
  }
  Pieces pieces(count, std::max(options.window, static_cast<std::size_t>(threads)), render);
  {
    std::vector<std::jthread> helpers;
    try {
      for (int t = 1; t < threads; ++t) helpers.emplace_back([&pieces] { pieces.help(); });
    } catch (const std::system_error&) {
      // No thread to be had: the caller renders the rest itself.
    }
    pieces.run(emit);
  }  // the helpers have stopped: run() set stop_ on every way out
  pieces.rethrow_failure();
}

int rendering_threads(std::size_t bytes) {
  if (bytes < kThreadedTextBytes) return 1;
  return std::min(hardware_workers(), 4);
}

}  // namespace covmap::io::detail
