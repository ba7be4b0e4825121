// covmap::io interrupt cleanup: what a run has half-written is removed when SIGINT, SIGTERM or
// SIGHUP stops it, and a run never stops half-way through putting its outputs in place.
//
// Contract:
// - install_interrupt_cleanup() (once, from main) installs handlers for SIGINT, SIGTERM and SIGHUP
//   and ignores SIGXFSZ, so that a file-size limit (`ulimit -f`) makes a write fail with EFBIG,
//   which covmap reports, instead of killing the process with a half-written temporary.
// - While a PendingPath is alive, an interrupting signal removes its path (a file, or an empty
//   folder; register a folder's files after the folder so they go first) before the process dies
//   of that signal. Up to kMaxPendingPaths paths at once; more throw std::length_error.
// - While a CriticalSection is alive, an interrupting signal is held back; it takes effect, with
//   the cleanup above, when the section ends. Outputs are moved into place inside one, so an
//   interrupt leaves either all old outputs or all new ones.
// The handler only calls async-signal-safe functions (unlink, rmdir, signal, raise).
// SIGKILL cannot be caught: its leftovers carry the dead process's id in their names
// (io/output_plan.h) and the next run that writes beside them removes them.
#pragma once

#include <cstddef>
#include <filesystem>

namespace covmap::io {

inline constexpr std::size_t kMaxPendingPaths = 64;

void install_interrupt_cleanup();

class PendingPath {
 public:
  explicit PendingPath(const std::filesystem::path& path);
  ~PendingPath();
  PendingPath(const PendingPath&) = delete;
  PendingPath& operator=(const PendingPath&) = delete;

 private:
  std::size_t slot_;
};

class CriticalSection {
 public:
  CriticalSection();
  ~CriticalSection();
  CriticalSection(const CriticalSection&) = delete;
  CriticalSection& operator=(const CriticalSection&) = delete;
};

}  // namespace covmap::io
