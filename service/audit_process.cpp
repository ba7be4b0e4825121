#include "service/audit_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <deque>
#include <stdexcept>

namespace covmap::service {
namespace {

constexpr std::size_t kStderrTailLines = 20;
constexpr const char* kProgressPrefix = "covmap audit: ";

// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void exec_child(const AuditProcessSpec& spec, const std::vector<char*>& argv, int stderr_write,
                             int stdout_fd) {
  setpgid(0, 0);  // its own process group, so a cancel kills everything it started
  sigset_t none;  // the server blocks SIGINT/SIGTERM in its threads; the audit takes them again
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  const rlimit cpu{static_cast<rlim_t>(spec.cpu_seconds), static_cast<rlim_t>(spec.cpu_seconds) + 5};
  setrlimit(RLIMIT_CPU, &cpu);
  const rlim_t bytes = static_cast<rlim_t>(spec.memory_mb) << 20;
  const rlimit memory{bytes, bytes};
  setrlimit(RLIMIT_AS, &memory);
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  dup2(stdout_fd, STDOUT_FILENO);
  dup2(stderr_write, STDERR_FILENO);
  const int null_in = open("/dev/null", O_RDONLY);
  if (null_in >= 0) dup2(null_in, STDIN_FILENO);
  execv(argv[0], argv.data());
  _exit(127);
}

// Reads what the child writes to stderr, line by line, until EOF; kills it when `cancel` is set.
void follow_stderr(int fd, pid_t child, const std::function<void(double, const std::string&)>& progress,
                   const std::atomic<bool>& cancel, bool& cancelled, std::deque<std::string>& tail) {
  std::string pending;
  char buffer[4096];
  for (;;) {
    if (cancel.load() && !cancelled) {
      kill(-child, SIGKILL);
      cancelled = true;
    }
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, kCancelPollMs);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    pending.append(buffer, static_cast<std::size_t>(n));
    for (std::size_t end; (end = pending.find('\n')) != std::string::npos;) {
      const std::string line = pending.substr(0, end);
      pending.erase(0, end + 1);
      ProgressLine parsed;
      if (parse_progress_line(line, parsed)) {
        if (progress) progress(parsed.fraction, parsed.stage);
      } else if (!line.empty()) {
        tail.push_back(line);
        if (tail.size() > kStderrTailLines) tail.pop_front();
      }
    }
  }
  if (!pending.empty()) tail.push_back(pending);
}

}  // namespace

bool parse_progress_line(const std::string& line, ProgressLine& out) {
  if (line.rfind(kProgressPrefix, 0) != 0) return false;
  std::string text = line.substr(std::strlen(kProgressPrefix));
  if (text.rfind("note:", 0) == 0 || text.rfind("warning:", 0) == 0) return false;
  // The elapsed time the CLI appends: " (1.2 s)".
  if (const auto open = text.rfind(" ("); open != std::string::npos && !text.empty() && text.back() == ')')
    text.erase(open);
  out = ProgressLine{};
  out.stage = text;
  if (text.size() >= 2 && text.compare(text.size() - 2, 2, " %") == 0) {
    const auto comma = text.rfind(", ");
    if (comma != std::string::npos) {
      try {
        out.fraction = std::stod(text.substr(comma + 2, text.size() - 2 - comma - 2)) / 100.0;
        out.stage = text.substr(0, comma);
      } catch (const std::exception&) {
        out.fraction = -1.0;
      }
    }
  }
  return true;
}

AuditProcessResult run_audit_process(const AuditProcessSpec& spec,
                                     const std::function<void(double, const std::string&)>& progress,
                                     const std::atomic<bool>& cancel) {
  std::vector<std::string> words{spec.program.string()};
  words.insert(words.end(), spec.args.begin(), spec.args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const int stdout_fd = open(spec.stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (stdout_fd < 0) throw std::runtime_error("cannot create " + spec.stdout_file.string() + ": " + std::strerror(errno));
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) {
    close(stdout_fd);
    throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
  }
  const pid_t child = fork();
  if (child < 0) {
    close(stdout_fd), close(pipe_fds[0]), close(pipe_fds[1]);
    throw std::runtime_error(std::string("cannot start an audit process: ") + std::strerror(errno));
  }
  if (child == 0) exec_child(spec, argv, pipe_fds[1], stdout_fd);
  close(pipe_fds[1]);
  close(stdout_fd);
  bool cancelled = false;
  std::deque<std::string> tail;
  follow_stderr(pipe_fds[0], child, progress, cancel, cancelled, tail);
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  AuditProcessResult result;
  for (const std::string& line : tail) result.stderr_tail += line + "\n";
  if (cancelled) {
    result.end = ProcessEnd::kCancelled;
  } else if (WIFEXITED(status)) {
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
    // SIGXCPU is the soft CPU limit's own signal. SIGKILL may be the hard CPU limit (5 s later, if
    // SIGXCPU was ignored) or the kernel's out-of-memory killer: not told apart, so a crash.
    result.end = result.signal == SIGXCPU ? ProcessEnd::kOutOfTime : ProcessEnd::kCrashed;
  }
  return result;
}

}  // namespace covmap::service
