#include "io/interrupt_cleanup.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <unistd.h>

namespace covmap::io {
namespace {

// Fixed storage, so the handler never touches the heap. A slot's text is written before `used` is
// set and `used` is cleared before the slot is reused, so the handler reads whole paths only.
constexpr std::size_t kMaxPathBytes = 4096;
char g_paths[kMaxPendingPaths][kMaxPathBytes];
std::atomic<bool> g_used[kMaxPendingPaths];     // the handler may read the slot
std::atomic<bool> g_claimed[kMaxPendingPaths];  // a PendingPath owns the slot
std::atomic<int> g_critical{0};
std::atomic<int> g_deferred_signal{0};

void remove_pending_paths() {
  for (std::size_t k = kMaxPendingPaths; k-- > 0;) {
    if (!g_used[k].load(std::memory_order_acquire)) continue;
    if (::unlink(g_paths[k]) != 0 && (errno == EISDIR || errno == EPERM)) ::rmdir(g_paths[k]);
  }
}

void die_of(int sig) {
  remove_pending_paths();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

extern "C" void on_interrupt(int sig) {
  if (g_critical.load() > 0) {
    g_deferred_signal.store(sig);
    return;
  }
  die_of(sig);
}

}  // namespace

void install_interrupt_cleanup() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_interrupt);
  std::signal(SIGXFSZ, SIG_IGN);
}

PendingPath::PendingPath(const std::filesystem::path& path) : slot_(kMaxPendingPaths) {
  const std::string text = path.string();
  if (text.size() >= kMaxPathBytes) throw std::length_error("path too long to guard: " + text);
  // The compare-exchange keeps two writing threads from taking the same slot.
  for (std::size_t k = 0; k < kMaxPendingPaths; ++k) {
    bool expected = false;
    if (!g_claimed[k].compare_exchange_strong(expected, true)) continue;
    std::memcpy(g_paths[k], text.c_str(), text.size() + 1);
    g_used[k].store(true, std::memory_order_release);
    slot_ = k;
    return;
  }
  throw std::length_error("more than " + std::to_string(kMaxPendingPaths) + " outputs pending at once");
}

PendingPath::~PendingPath() {
  g_used[slot_].store(false, std::memory_order_release);
  g_claimed[slot_].store(false);
}

CriticalSection::CriticalSection() { g_critical.fetch_add(1); }

CriticalSection::~CriticalSection() {
  if (g_critical.fetch_sub(1) == 1) {
    if (const int sig = g_deferred_signal.exchange(0); sig != 0) die_of(sig);
  }
}

}  // namespace covmap::io
