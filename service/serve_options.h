// covmap::service options: everything `covmap serve` can be told, with defaults that work out of
// the box on a laptop (loopback only, a data folder under the current directory, two audits at once).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace covmap::service {

struct ServeOptions {
  // Where to listen. Loopback by default: the service has no authentication, so exposing it is a
  // decision for whoever runs it (`--host 0.0.0.0`).
  std::string host = "127.0.0.1";
  // TCP port; 0 picks a free one (the server says which), which the tests use.
  int port = 8080;
  // Jobs, their uploads and their reports, and the SQLite job store (jobs.sqlite).
  std::filesystem::path data_dir = "covmap-data";
  // Audits running at once, each in a process of its own.
  int workers = 2;
  // Jobs waiting to run beyond which a submission is refused with 503 (try again later).
  std::size_t queue_limit = 100;
  // Largest request body (an upload of map + sensors), in MiB; larger ones get 413.
  std::size_t max_upload_mb = 256;
  // Largest body of a synchronous operation (/v1/diagram, /v1/check, ...), in MiB: beyond it the
  // answer is 413 with a pointer to the job API. (No body is ever larger than max_upload_mb.)
  std::size_t max_sync_mb = 8;
  // Limits of each audit's process: CPU seconds (RLIMIT_CPU) and address space in MiB (RLIMIT_AS).
  // An audit beyond them is killed and its job failed with the reason; the server is unaffected.
  int job_cpu_seconds = 3600;
  std::size_t job_memory_mb = 8192;
  // A job interrupted by a server stop (crash, kill) is run again up to this many attempts in all,
  // then failed with the reason.
  int max_attempts = 2;
  // The covmap program each audit runs as (`covmap audit ...`); empty: this program itself.
  std::filesystem::path worker_program;

  // True if every field is usable; otherwise false, with the reason in *why if why is not null.
  bool is_valid(std::string* why = nullptr) const;
};

}  // namespace covmap::service
