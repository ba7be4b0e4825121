// covmap::service job store: the jobs of `covmap serve`, kept in one SQLite database file so that
// they outlive the server process.
//
// JobStore::open(file) opens the database, creating the file and its schema when missing. The
// schema's version is PRAGMA user_version (kJobStoreSchemaVersion); a file written by a newer
// covmap (a higher version) and a SQLite file that holds other tables but no covmap schema are
// refused with a message saying so, and never changed. The journal is WAL, so that readers (GET
// requests) do not wait for a writer (a worker's progress), and busy_timeout lets other
// connections' writes finish instead of failing at once (kJobStoreBusyTimeoutMs).
//
// Accepted: a database file whose folder exists and is writable: a missing or empty file (the
// schema is created), or a covmap job store of this schema version. Jobs whose id is
// is_valid_job_id, any status, progress in [0, 1], and texts of any bytes; ids to look up of any
// text. Several JobStore objects and processes on one file.
//
// Guaranteed:
// - Every method is one SQLite transaction: it happens completely or not at all. A process killed
//   at any moment (SIGKILL, a crash) leaves a database that opens with every committed change and
//   none of an unfinished one. Durability is synchronous=NORMAL in WAL: committed transactions
//   survive the process dying; a power loss may lose the last ones but not the file's consistency.
// - Every method is thread-safe (one connection behind a mutex). Several processes may open the
//   same file: claim_next_queued takes the write lock before it reads, so two workers, threads or
//   processes, never take the same job.
// - After a restart nothing is left "running" once recover_interrupted ran: every job is queued
//   again or failed with the reason (error code "interrupted"). It must run before any worker
//   starts, by the one server that owns the data folder: it takes every running job for
//   interrupted.
// - Texts (options, summary, names, errors) come back byte for byte, UTF-8 or not.
//
// - The file's folder must be writable: WAL keeps two companion files beside it (<file>-wal,
//   <file>-shm) while connections are open.
// - After fork() a child must neither use nor destroy a JobStore it inherited (SQLite's rule for
//   connections): it opens its own, or leaves by exec or _exit.
//
// Rejected with std::invalid_argument: insert() of a job whose id is not is_valid_job_id (get()
// answers nullopt for such an id, the other methods false); a progress outside [0, 1] or NaN;
// finish() with a status that is not final; recover_interrupted() with max_attempts below 1.
// Failures of SQLite (unwritable folder, full disk, a file that is not a database, a lock held
// longer than the busy timeout) throw std::runtime_error
// "job store <file>: <operation>: <SQLite's message>", with the system's reason after an I/O
// error ("disk I/O error (No space left on device)"). A failed write changes nothing, and the
// store goes on working once the cause is gone.
//
// Not here: the uploaded files and results under the data folder (the server keeps them in a
// folder named after the job id); deleting a job's row does not touch them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "service/job.h"

namespace covmap::service {

// The schema this covmap writes and reads (PRAGMA user_version); a file of a higher one is refused.
inline constexpr int kJobStoreSchemaVersion = 1;
// How long a statement waits for another connection's lock before failing, in milliseconds.
inline constexpr int kJobStoreBusyTimeoutMs = 5000;
// The stage a job requeued by recover_interrupted shows until a worker takes it again.
inline constexpr std::string_view kRequeuedStage = "requeued after the server stopped";
// The error code of a job failed by recover_interrupted.
inline constexpr std::string_view kInterruptedErrorCode = "interrupted";

// What recover_interrupted did: the ids of the jobs queued again and of those failed, each in the
// order they had been created.
struct RecoveryReport {
  std::vector<std::string> requeued;
  std::vector<std::string> failed;
};

class JobStore {
 public:
  // Opens (or creates) the database at `file`; its folder must exist.
  static JobStore open(const std::filesystem::path& file);

  // A moved-from store may only be destroyed or assigned to.
  JobStore(JobStore&&) noexcept;
  JobStore& operator=(JobStore&&) noexcept;
  ~JobStore();

  // Adds a new job as given (normally queued, attempts 0). Throws if the id is invalid or taken.
  void insert(const Job& job);
  // The job with this id, or nullopt (also for an id that is not valid).
  std::optional<Job> get(std::string_view id) const;
  // At most `limit` jobs, newest first: created_ms descending, then id descending.
  std::vector<Job> list(std::size_t limit) const;
  // How many jobs have this status (for the queue's bound and health figures).
  std::size_t count_with_status(JobStatus status) const;

  // Takes the oldest queued job (created_ms, then id) and makes it running: started_ms = now_ms,
  // attempts + 1, progress 0, stage "". Returns it as stored, or nullopt when none is queued.
  std::optional<Job> claim_next_queued(std::int64_t now_ms);
  // Records a running job's progress (0..1) and stage. Returns false, changing nothing, when the
  // job is not running (cancelled, deleted, finished): the worker should then stop.
  bool set_progress(std::string_view id, double progress, std::string_view stage);
  // Ends a queued or running job: `status` is done, failed or cancelled; error and summary are
  // stored as given (a done job gets progress 1). Returns false, changing nothing, when the job
  // is already finished or gone (e.g. cancelled while it ran: the cancellation stands).
  bool finish(std::string_view id, JobStatus status, std::optional<JobError> error, std::string_view summary_json,
              std::int64_t now_ms);
  // Cancels a queued or running job (finished_ms = now_ms). Returns false when it is already
  // finished or does not exist. Stopping a running worker is the caller's business; the worker
  // learns of it from set_progress/finish returning false.
  bool cancel(std::string_view id, std::int64_t now_ms);
  // Deletes the job's row, whatever its status; returns false when there was none. Cancel a
  // running job first: its worker's later set_progress/finish then return false.
  bool remove(std::string_view id);

  // At server start, before any worker runs: every job still "running" was interrupted by the
  // previous server stopping. One with attempts < max_attempts goes back to queued (progress 0,
  // stage kRequeuedStage, started_ms 0); the others become failed with error code
  // kInterruptedErrorCode, a message giving the number of interruptions, `where` the stage they
  // were in, and finished_ms = now_ms. max_attempts must be at least 1.
  RecoveryReport recover_interrupted(int max_attempts, std::int64_t now_ms);

 private:
  struct Impl;
  explicit JobStore(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace covmap::service
