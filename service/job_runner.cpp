#include "service/job_runner.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/atomic_file.h"
#include "job/audit_outcome.h"
#include "job/audit_request_json.h"
#include "service/audit_process.h"
#include "service/audit_request.h"
#include "service/job_files.h"
#include "service/upload_check.h"

namespace covmap::service {
namespace {

// How long an idle worker sleeps before looking at the store again even without a wake(): jobs
// requeued by recovery, or queued by another server on the same store, are found within it.
constexpr auto kIdlePoll = std::chrono::milliseconds(500);

std::filesystem::path this_program() {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path("covmap") : self;
}

// The request a job's process runs: the options as submitted, the uploads, the job's report folder.
job::AuditRequest job_request(const Job& job, const JobFiles& files) {
  job::AuditRequest r = parse_audit_request(job.options_json);
  r.inputs.map = files.input_dir() / job.map_name;
  if (!job.sensors_name.empty()) r.inputs.sensors = files.input_dir() / job.sensors_name;
  r.outputs.folder = files.output_dir();
  r.command_line = "covmap serve: POST /v1/audits, job " + job.id + (job.options_json.empty() ? "" : ", options " + job.options_json);
  return r;
}

// The last non-empty line the process wrote on stderr, for a process that died before saying how
// the audit ended.
std::string last_line(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

// How the process ended, as the job's final state.
struct Outcome {
  JobStatus status = JobStatus::kFailed;
  std::optional<JobError> error;
  std::string summary;  // done: the audit's summary, JSON text
};

// The outcome record the process left (job/audit_outcome.h), said as the API says it.
Outcome recorded_outcome(const AuditProcessResult& r, const JobFiles& files, const job::AuditRequest& request) {
  job::AuditOutcome recorded;
  try {
    std::ifstream in(files.outcome_file(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    recorded = job::outcome_from_json(text.str());
  } catch (const std::exception&) {
    const std::string said = last_line(r.stderr_tail);
    return {JobStatus::kFailed,
            JobError{"internal",
                     "the audit's process ended (exit " + std::to_string(r.exit_code) + ") without recording how the audit "
                         "ended" + (said.empty() ? std::string() : ": " + without_server_paths(said, request)),
                     ""},
            ""};
  }
  if (recorded.done) return {JobStatus::kDone, std::nullopt, recorded.summary_json};
  const job::AuditFailure& f = recorded.failure.value();
  std::string where(job::input_kind_name(f.input));
  if (!f.item.empty()) where += (where.empty() ? "" : ": ") + f.item;
  return {JobStatus::kFailed, JobError{std::string(job::failure_kind_name(f.kind)), without_server_paths(f.message, request), where}, ""};
}

Outcome outcome_of(const AuditProcessResult& r, const ServeOptions& o, const JobFiles& files, const job::AuditRequest& request) {
  switch (r.end) {
    case ProcessEnd::kCancelled: return {JobStatus::kCancelled, std::nullopt, ""};
    case ProcessEnd::kOutOfTime:
      return {JobStatus::kFailed, JobError{"resource_limit",
                                           "the audit ran out of its CPU time (" + std::to_string(o.job_cpu_seconds) +
                                               " s, `covmap serve --job-cpu-seconds`)",
                                           ""}, ""};
    case ProcessEnd::kCrashed:
      return {JobStatus::kFailed,
              JobError{"crashed",
                       "the audit's process was killed by signal " + std::to_string(r.signal) + " (" + strsignal(r.signal) +
                           "; SIGKILL is also how the system ends a process out of memory or past its hard CPU "
                           "limit; limits " + std::to_string(o.job_memory_mb) + " MiB, " +
                           std::to_string(o.job_cpu_seconds) + " s)",
                       ""}, ""};
    case ProcessEnd::kExited: break;
  }
  return recorded_outcome(r, files, request);
}

}  // namespace

std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

JobRunner::JobRunner(JobStore& store, const ServeOptions& options) : store_(store), options_(options) {
  if (options_.worker_program.empty()) options_.worker_program = this_program();
  for (int i = 0; i < options_.workers; ++i) threads_.emplace_back([this] { work(); });
}

JobRunner::~JobRunner() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    for (auto& [id, flag] : cancel_flags_) flag->store(true);
  }
  stop_all_ = true;
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void JobRunner::wake() { wake_.notify_one(); }

bool JobRunner::cancel_running(const std::string& id) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = cancel_flags_.find(id);
  if (it == cancel_flags_.end()) return false;
  it->second->store(true);
  return true;
}

std::size_t JobRunner::running() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return cancel_flags_.size();
}

void JobRunner::work() {
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      if (stopping_) return;
    }
    std::optional<Job> job = store_.claim_next_queued(now_ms());
    if (!job) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait_for(lock, kIdlePoll, [this] { return stopping_; });
      continue;
    }
    run(*job);
  }
}

void JobRunner::run(const Job& job) {
  const auto flag = std::make_shared<std::atomic<bool>>(false);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return;  // left "running": the next start requeues it
    cancel_flags_[job.id] = flag;
  }
  const JobFiles files = job_files(options_.data_dir, job.id);
  Outcome outcome;
  try {
    const job::AuditRequest request = job_request(job, files);
    std::filesystem::remove_all(files.output_dir());  // a requeued job starts clean
    std::filesystem::remove(files.outcome_file());
    io::write_files_atomically({{files.request_file(), job::request_json(request)}});
    AuditProcessSpec spec;
    spec.program = options_.worker_program;
    spec.args = {"audit-job", files.request_file().string(), files.outcome_file().string()};
    spec.stdout_file = files.stdout_file();
    spec.cpu_seconds = options_.job_cpu_seconds;
    spec.memory_mb = options_.job_memory_mb;
    double fraction_so_far = 0.0;  // a line naming only a stage keeps the fraction reached
    const AuditProcessResult result = run_audit_process(
        spec,
        [&](double fraction, const std::string& stage) {
          if (fraction >= 0) fraction_so_far = std::min(fraction, 1.0);
          // False: the job is no longer running in the store (cancelled by a request): stop it.
          if (!store_.set_progress(job.id, fraction_so_far, stage)) flag->store(true);
        },
        *flag);
    outcome = outcome_of(result, options_, files, request);
  } catch (const std::exception& e) {
    outcome = {JobStatus::kFailed, JobError{"internal", e.what(), ""}, ""};
  }
  bool stopping = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cancel_flags_.erase(job.id);
    stopping = stopping_;
  }
  // Killed because the server is stopping: not the job's fault; recovery will run it again.
  if (stopping && outcome.status == JobStatus::kCancelled) return;
  store_.finish(job.id, outcome.status, outcome.error, outcome.summary, now_ms());
}

}  // namespace covmap::service
