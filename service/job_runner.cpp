#include "service/job_runner.h"

#include <nlohmann/json.hpp>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>

#include "service/audit_process.h"
#include "service/audit_request.h"
#include "service/job_files.h"

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

// report.json's "summary" (the counts by verdict and the agreement), as JSON text.
std::string summary_of(const std::filesystem::path& report_json) {
  std::ifstream in(report_json);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("summary")) return "";
  return j["summary"].dump();
}

// The last non-empty line the audit wrote on stderr: covmap's own error message.
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
};

Outcome outcome_of(const AuditProcessResult& r, const ServeOptions& o) {
  switch (r.end) {
    case ProcessEnd::kCancelled: return {JobStatus::kCancelled, std::nullopt};
    case ProcessEnd::kOutOfTime:
      return {JobStatus::kFailed, JobError{"resource_limit",
                                           "the audit ran out of its CPU time (" + std::to_string(o.job_cpu_seconds) +
                                               " s, `covmap serve --job-cpu-seconds`)",
                                           ""}};
    case ProcessEnd::kCrashed:
      return {JobStatus::kFailed,
              JobError{"crashed",
                       "the audit's process was killed by signal " + std::to_string(r.signal) + " (" + strsignal(r.signal) +
                           "; SIGKILL is also how the system ends a process out of memory or past its hard CPU "
                           "limit; limits " + std::to_string(o.job_memory_mb) + " MiB, " +
                           std::to_string(o.job_cpu_seconds) + " s)",
                       ""}};
    case ProcessEnd::kExited: break;
  }
  if (r.exit_code == 0 || r.exit_code == 1) return {JobStatus::kDone, std::nullopt};
  const std::string said = last_line(r.stderr_tail);
  if (r.exit_code == 2) return {JobStatus::kFailed, JobError{"bad_input", said, ""}};
  return {JobStatus::kFailed, JobError{"internal", said.empty() ? "exit " + std::to_string(r.exit_code) : said, ""}};
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
  std::string summary;
  try {
    const AuditRequest request = parse_audit_request(job.options_json);
    const auto sensors = job.sensors_name.empty() ? std::filesystem::path() : files.input_dir() / job.sensors_name;
    std::filesystem::remove_all(files.output_dir());  // a requeued job starts clean
    AuditProcessSpec spec;
    spec.program = options_.worker_program;
    spec.args = audit_arguments(request, files.input_dir() / job.map_name, sensors, files.output_dir());
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
    outcome = outcome_of(result, options_);
    if (outcome.status == JobStatus::kDone) summary = summary_of(files.output_dir() / "report.json");
  } catch (const std::exception& e) {
    outcome = {JobStatus::kFailed, JobError{"internal", e.what(), ""}};
  }
  bool stopping = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cancel_flags_.erase(job.id);
    stopping = stopping_;
  }
  // Killed because the server is stopping: not the job's fault; recovery will run it again.
  if (stopping && outcome.status == JobStatus::kCancelled) return;
  store_.finish(job.id, outcome.status, outcome.error, summary, now_ms());
}

}  // namespace covmap::service
