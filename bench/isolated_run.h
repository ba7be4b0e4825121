// Running one benchmark row in a child process, so that its peak memory is its own and not the
// high-water mark of every earlier row, and reading the process's memory counters (Linux only).
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace covmap::bench {

struct IsolatedResult {
  bool ok = false;           // the child exited with status 0
  std::string output;        // everything the body returned (written through a pipe)
  std::string failure;       // why not ok: the exception text, the exit status or the signal
  long peak_rss_kib = 0;     // ru_maxrss of the child (wait4), the whole process's peak RSS
};

// Forks; the child runs `body` and sends its return value back; the parent waits for it. An
// exception in the body is reported as a failure with its what() text.
IsolatedResult run_isolated(const std::function<std::string()>& body);

// /proc/self/status VmRSS and VmHWM in KiB; nullopt when unavailable.
std::optional<long> current_rss_kib();
std::optional<long> peak_rss_kib();

// Resets VmHWM to the current RSS (writes 5 to /proc/self/clear_refs, Linux ≥ 4.0), so that a
// following peak_rss_kib() is the peak of what ran in between. False when not supported.
bool reset_peak_rss();

}  // namespace covmap::bench
