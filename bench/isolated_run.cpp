#include "bench/isolated_run.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>

namespace covmap::bench {

namespace {

bool write_all(int fd, const std::string& data) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t k = ::write(fd, data.data() + done, data.size() - done);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    done += static_cast<std::size_t>(k);
  }
  return true;
}

std::optional<long> status_field_kib(const std::string& key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + ":", 0) == 0) return std::stol(line.substr(key.size() + 1));  // "... kB"
  return std::nullopt;
}

}  // namespace

IsolatedResult run_isolated(const std::function<std::string()>& body) {
  IsolatedResult result;
  int fds[2];
  if (::pipe(fds) != 0) {
    result.failure = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    result.failure = std::string("fork: ") + std::strerror(errno);
    ::close(fds[0]);
    ::close(fds[1]);
    return result;
  }
  if (pid == 0) {  // child: never returns into the caller's code
    ::close(fds[0]);
    int status = 0;
    std::string out;
    try {
      out = body();
    } catch (const std::exception& e) {
      out = e.what();
      status = 2;
    } catch (...) {
      out = "unknown exception";
      status = 2;
    }
    if (!write_all(fds[1], out)) status = 3;
    ::close(fds[1]);
    ::_exit(status);
  }
  ::close(fds[1]);
  std::string received;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t k = ::read(fds[0], buffer, sizeof buffer);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;
    received.append(buffer, static_cast<std::size_t>(k));
  }
  ::close(fds[0]);
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  result.peak_rss_kib = usage.ru_maxrss;  // KiB on Linux
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    result.ok = true;
    result.output = std::move(received);
  } else if (WIFEXITED(status)) {
    result.failure = "child exited with status " + std::to_string(WEXITSTATUS(status)) +
                     (received.empty() ? "" : ": " + received);
  } else if (WIFSIGNALED(status)) {
    result.failure = "child killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                     ::strsignal(WTERMSIG(status)) + ")";
  } else {
    result.failure = "child ended abnormally";
  }
  return result;
}

std::optional<long> current_rss_kib() { return status_field_kib("VmRSS"); }
std::optional<long> peak_rss_kib() { return status_field_kib("VmHWM"); }

bool reset_peak_rss() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

}  // namespace covmap::bench
