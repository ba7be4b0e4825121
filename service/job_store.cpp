#include "service/job_store.h"

#include <algorithm>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "core/readable_numbers.h"
#include "service/job_schema.h"
#include "service/sqlite_db.h"

namespace covmap::service {

struct JobStore::Impl {
  explicit Impl(const std::filesystem::path& file) : db(file) {}
  std::mutex mutex;
  sqlite::Database db;
};

namespace {

using Lock = std::lock_guard<std::mutex>;

std::string status_text(JobStatus status) { return std::string(job_status_name(status)); }

void check_progress(double progress) {
  if (!(progress >= 0 && progress <= 1)) {
    throw std::invalid_argument("job progress must be within [0, 1], not " + std::to_string(progress));
  }
}

// Reads the columns of kJobColumns, in that order, from the statement's current row.
Job job_from_row(const sqlite::Database& db, const sqlite::Statement& row) {
  Job job;
  job.id = row.text(0);
  const std::string status = row.text(1);
  const std::optional<JobStatus> parsed = job_status_from_name(status);
  if (!parsed) throw db.error("read job " + job.id, "unknown status '" + status + "'");
  job.status = *parsed;
  job.progress = row.real(2);
  job.stage = row.text(3);
  if (std::optional<std::string> code = row.optional_text(4)) {
    job.error = JobError{std::move(*code), row.text(5), row.text(6)};
  }
  job.summary_json = row.text(7);
  job.options_json = row.text(8);
  job.map_name = row.text(9);
  job.sensors_name = row.text(10);
  job.created_ms = row.integer(11);
  job.started_ms = row.integer(12);
  job.finished_ms = row.integer(13);
  job.attempts = static_cast<int>(row.integer(14));
  return job;
}

// Binds an optional error to three consecutive parameters from `first` (all NULL without one).
void bind_error(sqlite::Statement& statement, int first, const std::optional<JobError>& error) {
  if (!error) {
    for (int i = 0; i < 3; ++i) statement.bind_null(first + i);
    return;
  }
  statement.bind(first, error->code).bind(first + 1, error->message).bind(first + 2, error->where);
}

std::string select_jobs(std::string_view rest) { return "SELECT " + std::string(kJobColumns) + " FROM jobs " + std::string(rest); }

// The error of a job interrupted `attempts` times and not run again.
JobError interrupted_error(std::int64_t attempts, int max_attempts, const std::string& stage) {
  return JobError{std::string(kInterruptedErrorCode),
                  "the audit was interrupted " + plural(static_cast<std::size_t>(attempts), "time") +
                      " by the server stopping and is not run again (at most " +
                      plural(static_cast<std::size_t>(max_attempts), "attempt") + ")",
                  stage.empty() ? std::string() : "stage: " + stage};
}

}  // namespace

JobStore::JobStore(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
JobStore::JobStore(JobStore&&) noexcept = default;
JobStore& JobStore::operator=(JobStore&&) noexcept = default;
JobStore::~JobStore() = default;

JobStore JobStore::open(const std::filesystem::path& file) {
  auto impl = std::make_unique<Impl>(file);
  prepare_job_schema(impl->db);
  return JobStore(std::move(impl));
}

void JobStore::insert(const Job& job) {
  if (!is_valid_job_id(job.id)) throw std::invalid_argument("invalid job id '" + job.id + "'");
  check_progress(job.progress);
  const Lock lock(impl_->mutex);
  sqlite::Statement insert(impl_->db,
                           "INSERT INTO jobs (" + std::string(kJobColumns) +
                               ") VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15)",
                           "insert job " + job.id);
  insert.bind(1, job.id).bind(2, job_status_name(job.status)).bind(3, job.progress).bind(4, job.stage);
  bind_error(insert, 5, job.error);
  insert.bind(8, job.summary_json).bind(9, job.options_json).bind(10, job.map_name).bind(11, job.sensors_name);
  insert.bind(12, job.created_ms).bind(13, job.started_ms).bind(14, job.finished_ms);
  insert.bind(15, static_cast<std::int64_t>(job.attempts));
  insert.run();
}

std::optional<Job> JobStore::get(std::string_view id) const {
  if (!is_valid_job_id(id)) return std::nullopt;
  const Lock lock(impl_->mutex);
  sqlite::Statement query(impl_->db, select_jobs("WHERE id = ?1"), "read job " + std::string(id));
  query.bind(1, id);
  if (!query.step()) return std::nullopt;
  return job_from_row(impl_->db, query);
}

std::vector<Job> JobStore::list(std::size_t limit) const {
  const auto max_limit = static_cast<std::size_t>(std::numeric_limits<std::int64_t>::max());
  const Lock lock(impl_->mutex);
  sqlite::Statement query(impl_->db, select_jobs("ORDER BY created_ms DESC, id DESC LIMIT ?1"), "list jobs");
  query.bind(1, static_cast<std::int64_t>(std::min(limit, max_limit)));
  std::vector<Job> jobs;
  while (query.step()) jobs.push_back(job_from_row(impl_->db, query));
  return jobs;
}

std::size_t JobStore::count_with_status(JobStatus status) const {
  const Lock lock(impl_->mutex);
  sqlite::Statement query(impl_->db, "SELECT count(*) FROM jobs WHERE status = ?1",
                          "count " + status_text(status) + " jobs");
  query.bind(1, job_status_name(status));
  return query.step() ? static_cast<std::size_t>(query.integer(0)) : 0;
}

std::optional<Job> JobStore::claim_next_queued(std::int64_t now_ms) {
  const Lock lock(impl_->mutex);
  const std::string operation = "claim the next queued job";
  sqlite::Transaction transaction(impl_->db, operation);
  std::optional<Job> claimed;
  {
    sqlite::Statement claim(impl_->db,
                            "UPDATE jobs SET status = ?1, started_ms = ?2, attempts = attempts + 1, progress = 0, "
                            "stage = '' WHERE id = (SELECT id FROM jobs WHERE status = ?3 "
                            "ORDER BY created_ms, id LIMIT 1) RETURNING " + std::string(kJobColumns),
                            operation);
    claim.bind(1, job_status_name(JobStatus::kRunning)).bind(2, now_ms).bind(3, job_status_name(JobStatus::kQueued));
    if (claim.step()) claimed = job_from_row(impl_->db, claim);
    claim.run();  // a RETURNING statement must finish before the transaction commits
  }
  transaction.commit();
  return claimed;
}

bool JobStore::set_progress(std::string_view id, double progress, std::string_view stage) {
  check_progress(progress);
  const Lock lock(impl_->mutex);
  sqlite::Statement update(impl_->db, "UPDATE jobs SET progress = ?1, stage = ?2 WHERE id = ?3 AND status = ?4",
                           "record the progress of job " + std::string(id));
  update.bind(1, progress).bind(2, stage).bind(3, id).bind(4, job_status_name(JobStatus::kRunning));
  update.run();
  return impl_->db.changes() > 0;
}

bool JobStore::finish(std::string_view id, JobStatus status, std::optional<JobError> error,
                      std::string_view summary_json, std::int64_t now_ms) {
  if (!is_finished(status)) {
    throw std::invalid_argument("a job cannot finish as '" + status_text(status) +
                                "': done, failed or cancelled are the final states");
  }
  const Lock lock(impl_->mutex);
  sqlite::Statement update(impl_->db,
                           "UPDATE jobs SET status = ?1, error_code = ?2, error_message = ?3, error_where = ?4, "
                           "summary_json = ?5, finished_ms = ?6, progress = CASE WHEN ?1 = ?7 THEN 1 ELSE progress END "
                           "WHERE id = ?8 AND status IN (?9, ?10)",
                           "finish job " + std::string(id));
  update.bind(1, job_status_name(status));
  bind_error(update, 2, error);
  update.bind(5, summary_json).bind(6, now_ms).bind(7, job_status_name(JobStatus::kDone)).bind(8, id);
  update.bind(9, job_status_name(JobStatus::kQueued)).bind(10, job_status_name(JobStatus::kRunning));
  update.run();
  return impl_->db.changes() > 0;
}

bool JobStore::cancel(std::string_view id, std::int64_t now_ms) {
  const Lock lock(impl_->mutex);
  sqlite::Statement update(impl_->db, "UPDATE jobs SET status = ?1, finished_ms = ?2 WHERE id = ?3 AND status IN (?4, ?5)",
                           "cancel job " + std::string(id));
  update.bind(1, job_status_name(JobStatus::kCancelled)).bind(2, now_ms).bind(3, id);
  update.bind(4, job_status_name(JobStatus::kQueued)).bind(5, job_status_name(JobStatus::kRunning));
  update.run();
  return impl_->db.changes() > 0;
}

bool JobStore::remove(std::string_view id) {
  const Lock lock(impl_->mutex);
  sqlite::Statement erase(impl_->db, "DELETE FROM jobs WHERE id = ?1", "delete job " + std::string(id));
  erase.bind(1, id).run();
  return impl_->db.changes() > 0;
}

RecoveryReport JobStore::recover_interrupted(int max_attempts, std::int64_t now_ms) {
  if (max_attempts < 1) throw std::invalid_argument("max_attempts must be at least 1");
  const Lock lock(impl_->mutex);
  const std::string operation = "recover interrupted jobs";
  sqlite::Transaction transaction(impl_->db, operation);
  struct Interrupted {
    std::string id;
    std::int64_t attempts;
    std::string stage;
  };
  std::vector<Interrupted> interrupted;
  {
    sqlite::Statement query(impl_->db, "SELECT id, attempts, stage FROM jobs WHERE status = ?1 ORDER BY created_ms, id",
                            operation);
    query.bind(1, job_status_name(JobStatus::kRunning));
    while (query.step()) interrupted.push_back({query.text(0), query.integer(1), query.text(2)});
  }
  RecoveryReport report;
  for (const Interrupted& job : interrupted) {
    if (job.attempts < max_attempts) {
      sqlite::Statement requeue(impl_->db, "UPDATE jobs SET status = ?1, progress = 0, stage = ?2, started_ms = 0 WHERE id = ?3",
                                operation);
      requeue.bind(1, job_status_name(JobStatus::kQueued)).bind(2, kRequeuedStage).bind(3, job.id).run();
      report.requeued.push_back(job.id);
      continue;
    }
    sqlite::Statement fail(impl_->db,
                           "UPDATE jobs SET status = ?1, error_code = ?2, error_message = ?3, error_where = ?4, "
                           "finished_ms = ?5 WHERE id = ?6",
                           operation);
    fail.bind(1, job_status_name(JobStatus::kFailed));
    bind_error(fail, 2, interrupted_error(job.attempts, max_attempts, job.stage));
    fail.bind(5, now_ms).bind(6, job.id).run();
    report.failed.push_back(job.id);
  }
  transaction.commit();
  return report;
}

}  // namespace covmap::service
