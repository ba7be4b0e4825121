// covmap::service audit processes: one audit runs as `covmap audit-job REQUEST OUTCOME`
// (cli/audit_job_command.h) in a child process of its own, so that a crash, a runaway input or a
// memory blow-up ends that job and never the server.
//
// Contract: run_audit_process forks; the child sets its limits (RLIMIT_CPU, RLIMIT_AS, no core
// files), asks the kernel to kill it if the server dies (PR_SET_PDEATHSIG: no orphan keeps writing
// into a job's folder after a restart), sends stdout to `stdout_file` and stderr to a pipe, and
// execs the program. The parent reads the child's progress lines ("covmap audit: STAGE, N % (T)")
// and calls `progress` with N/100 and STAGE; it polls `cancel` at least every kCancelPollMs and
// kills the child's process group when it is set. Returns when the child has exited and been
// reaped: never leaves a zombie. Throws std::runtime_error only if the process cannot be started.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace covmap::service {

struct AuditProcessSpec {
  std::filesystem::path program;     // the covmap executable
  std::vector<std::string> args;     // after the program name: "audit", MAP, "--sensors", ...
  std::filesystem::path stdout_file; // the audit's summary lines
  int cpu_seconds = 3600;
  std::size_t memory_mb = 8192;
};

enum class ProcessEnd {
  kExited,     // exit code in exit_code
  kCancelled,  // killed because `cancel` was set
  kOutOfTime,  // killed by RLIMIT_CPU's SIGXCPU
  kCrashed,    // killed by another signal (SIGSEGV, SIGABRT, SIGKILL: an out-of-memory kill or the hard CPU limit)
};

struct AuditProcessResult {
  ProcessEnd end = ProcessEnd::kExited;
  int exit_code = 0;         // kExited only
  int signal = 0;            // the killing signal otherwise
  std::string stderr_tail;   // the last lines the audit wrote to stderr that were not progress
};

inline constexpr int kCancelPollMs = 100;

AuditProcessResult run_audit_process(const AuditProcessSpec& spec,
                                     const std::function<void(double fraction, const std::string& stage)>& progress,
                                     const std::atomic<bool>& cancel);

// One progress line of `covmap audit` read: "covmap audit: refining sites, 40 % (1.2 s)" gives
// (0.4, "refining sites"); a line without a percentage gives the stage and a negative fraction;
// a line that is not progress ("covmap: ...", a warning) gives nothing.
struct ProgressLine {
  double fraction = -1.0;
  std::string stage;
};
bool parse_progress_line(const std::string& line, ProgressLine& out);

}  // namespace covmap::service
