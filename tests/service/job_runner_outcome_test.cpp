// The job runner learns how a job ended from the outcome record its process leaves
// (job/audit_outcome.h), not from the process's messages. A stand-in program plays the job's
// process: it records a given outcome (or none), and the job's state in the store is checked
// against what was recorded — with the server's paths out of the message.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "job/audit_outcome.h"
#include "job/audit_request_json.h"
#include "service/job_files.h"
#include "service/job_runner.h"
#include "service/job_store.h"
#include "service_test_util.h"

namespace covmap::service {
namespace {

// A program that keeps the request it was given beside it and writes `outcome` (none if empty)
// where it is told to, then says `stderr_text` and exits 0.
std::filesystem::path stand_in(const std::filesystem::path& dir, const std::string& outcome, const std::string& stderr_text) {
  const auto script = dir / "stand-in.sh";
  if (!outcome.empty()) std::ofstream(dir / "outcome.txt") << outcome;
  std::ofstream(script) << "#!/bin/sh\n"
                        << "[ \"$1\" = audit-job ] || exit 9\n"
                        << "cp \"$2\" '" << (dir / "request-seen.json").string() << "'\n"
                        << (outcome.empty() ? "" : "cp '" + (dir / "outcome.txt").string() + "' \"$3\"\n")
                        << "echo '" << stderr_text << "' >&2\n";
  ::chmod(script.c_str(), 0755);
  return script;
}

// Runs one queued job (map.geojson, no sensors) through a runner whose worker is `program`.
Job run_one(const std::filesystem::path& data, const std::filesystem::path& program, const std::string& id) {
  JobStore store = JobStore::open(job_store_file(data));
  Job job = testing::queued_job(1);
  job.id = id;
  job.map_name = "map.geojson";
  job.options_json = R"({"alpha": 3.5})";
  store.insert(job);
  ServeOptions options;
  options.data_dir = data;
  options.workers = 1;
  options.worker_program = program;
  JobRunner runner(store, options);
  runner.wake();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline) {
    const std::optional<Job> now = store.get(id);
    if (now && is_finished(now->status)) return *now;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ADD_FAILURE() << "the job did not finish";
  return job;
}

TEST(JobRunnerOutcome, FailureRecordedBecomesTheJobsErrorWithoutServerPaths) {
  testing::ScratchFolder data;
  const std::string id = new_job_id();
  const auto map = job_files(data.path(), id).input_dir() / "map.geojson";
  job::AuditFailure failure{job::FailureKind::kBadInput, map.string() + ":3: features[1]: ring not closed",
                            job::AuditInputKind::kMap, "features[1]"};
  const Job done = run_one(data.path(), stand_in(data.path(), job::outcome_json(job::failed_outcome(failure)), "noise"), id);
  EXPECT_EQ(done.status, JobStatus::kFailed);
  ASSERT_TRUE(done.error);
  EXPECT_EQ(done.error->code, "bad_input");
  EXPECT_EQ(done.error->message, "map:3: features[1]: ring not closed");
  EXPECT_EQ(done.error->where, "map: features[1]");
  // The process was given the job's request: its upload, its folder, its options.
  std::ifstream in(data.path() / "request-seen.json");
  const job::AuditRequest seen = job::request_from_json(std::string(std::istreambuf_iterator<char>(in), {}));
  EXPECT_EQ(seen.inputs.map, map);
  EXPECT_TRUE(seen.inputs.sensors.empty());
  EXPECT_EQ(seen.outputs.folder, job_files(data.path(), id).output_dir());
  EXPECT_EQ(seen.settings.alpha, 3.5);
}

TEST(JobRunnerOutcome, DoneRecordedBecomesTheJobsSummary) {
  testing::ScratchFolder data;
  job::AuditOutcome outcome;
  outcome.done = true;
  outcome.summary_json = R"({"consistent":3,"sensors":3})";
  const Job done = run_one(data.path(), stand_in(data.path(), job::outcome_json(outcome), ""), new_job_id());
  EXPECT_EQ(done.status, JobStatus::kDone);
  EXPECT_FALSE(done.error);
  EXPECT_EQ(done.summary_json, outcome.summary_json);
}

TEST(JobRunnerOutcome, AProcessThatRecordsNothingFailsTheJobAsInternal) {
  testing::ScratchFolder data;
  const Job done = run_one(data.path(), stand_in(data.path(), "", "covmap: something broke"), new_job_id());
  EXPECT_EQ(done.status, JobStatus::kFailed);
  ASSERT_TRUE(done.error);
  EXPECT_EQ(done.error->code, "internal");
  EXPECT_NE(done.error->message.find("without recording"), std::string::npos) << done.error->message;
  EXPECT_NE(done.error->message.find("something broke"), std::string::npos) << done.error->message;
}

}  // namespace
}  // namespace covmap::service
