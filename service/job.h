// covmap::service jobs: one audit submitted to `covmap serve`, as plain data.
//
// A job moves queued -> running -> done | failed | cancelled; a running job may also go back to
// queued when the server stopped under it (JobStore::recover_interrupted). done, failed and
// cancelled are final (is_finished). JobStatus is a closed set: job_status_name and
// job_status_from_name are the only spelling of it, in the store and in the HTTP API alike.
//
// Job ids are 32 lowercase hexadecimal characters (128 random bits from std::random_device,
// new_job_id). An id is also a folder name under the service's data folder, so is_valid_job_id
// accepts exactly that shape and nothing else: a request naming "../x", an uppercase or a short id
// is refused before it reaches the file system or the store.
//
// Times are Unix milliseconds (unix_now_ms), 0 meaning "not yet". Nothing here checks the texts a
// job carries (options, summary, file names): they are kept and returned byte for byte.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace covmap::service {

enum class JobStatus { kQueued, kRunning, kDone, kFailed, kCancelled };

// Every status, in the order of the enum (for loops over the closed set).
inline constexpr std::array<JobStatus, 5> kAllJobStatuses = {
    JobStatus::kQueued, JobStatus::kRunning, JobStatus::kDone, JobStatus::kFailed, JobStatus::kCancelled};

// "queued", "running", "done", "failed", "cancelled".
std::string_view job_status_name(JobStatus status);
// The status so named (exact, lowercase), or nullopt for any other text.
std::optional<JobStatus> job_status_from_name(std::string_view name);
// done, failed or cancelled: the job will not change any more.
bool is_finished(JobStatus status);

// Why a job failed, in the shape of the API's JSON errors: a stable code ("interrupted",
// "invalid_input", ...), a sentence for people, and where in the input (part, feature, line) or
// the pipeline (stage) it happened; `where` may be empty.
struct JobError {
  std::string code;
  std::string message;
  std::string where;

  friend bool operator==(const JobError&, const JobError&) = default;
};

struct Job {
  std::string id;
  JobStatus status = JobStatus::kQueued;
  double progress = 0;  // 0..1, of the current attempt
  std::string stage;    // what the running audit is doing, for people ("fitting sites")
  std::optional<JobError> error;  // set when failed
  std::string summary_json;       // the audit's summary as JSON text, or empty until done
  std::string options_json;       // the options as submitted (JSON text, may be empty)
  std::string map_name;           // the uploaded map's file name
  std::string sensors_name;       // the uploaded sensors file's name, empty without one
  std::int64_t created_ms = 0;    // submitted
  std::int64_t started_ms = 0;    // the current (last) attempt started; 0 while queued
  std::int64_t finished_ms = 0;   // reached done, failed or cancelled; 0 before
  int attempts = 0;               // how many times a worker took the job (claim_next_queued)

  friend bool operator==(const Job&, const Job&) = default;
};

// 128 bits from std::random_device as 32 lowercase hexadecimal characters.
std::string new_job_id();
// Exactly 32 characters, each 0-9 or a-f.
bool is_valid_job_id(std::string_view id);

// The system clock now, in Unix milliseconds.
std::int64_t unix_now_ms();

}  // namespace covmap::service
