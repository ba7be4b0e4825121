// covmap::service job runner: `workers` threads take queued jobs from the store, run each as an
// audit process (service/audit_process.h) with the configured limits, keep the store's progress up
// to date, and record how each ended: done (with the report's summary), failed (with the reason:
// bad input, an internal error, a resource limit, a crash), or cancelled.
//
// Contract: a job is run by exactly one worker (the store's claim is atomic). cancel() kills a
// running job's process within kCancelPollMs; a queued one is cancelled by the store directly. The
// destructor stops the workers: running audits are killed and their jobs stay "running" in the
// store, which the next start's recovery requeues (JobStore::recover_interrupted), exactly as
// after a crash — one path for every way a server can stop.
#pragma once

#include <atomic>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "service/job_store.h"
#include "service/serve_options.h"

namespace covmap::service {

class JobRunner {
 public:
  JobRunner(JobStore& store, const ServeOptions& options);
  ~JobRunner();
  JobRunner(const JobRunner&) = delete;
  JobRunner& operator=(const JobRunner&) = delete;

  // A job was queued: wake a worker.
  void wake();
  // Kills the job's process if one of the workers runs it; false if none does.
  bool cancel_running(const std::string& id);
  // Jobs running now.
  std::size_t running() const;

 private:
  void work();
  void run(const Job& job);

  JobStore& store_;
  ServeOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::map<std::string, std::shared_ptr<std::atomic<bool>>> cancel_flags_;  // by running job id
  std::atomic<bool> stop_all_{false};
  std::vector<std::thread> threads_;
};

// The current time in Unix milliseconds (the store's clock).
std::int64_t now_ms();

}  // namespace covmap::service
