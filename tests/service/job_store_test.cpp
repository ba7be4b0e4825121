#include "service/job_store.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "service_test_util.h"

namespace covmap::service {
namespace {

using testing::queued_job;
using testing::ScratchFolder;

// A finished job with every field away from its default, and texts that a careless store would
// mangle: quotes, backslashes, newlines, SQL, UTF-8 and a NUL byte.
Job job_with_every_field() {
  Job job;
  job.id = new_job_id();
  job.status = JobStatus::kFailed;
  job.progress = 0.375;
  job.stage = "fitting sites — Zürich 北京";
  job.error = JobError{"invalid_input", "feature 3: \"sensor\" is '' ; DROP TABLE jobs; --\nsecond line",
                       std::string("features[3]\0tail", 16)};
  job.summary_json = R"({"verdict": "not_mwvd", "note": "a \"quoted\" word, a \\ and é"})";
  job.options_json = R"({"alpha": 3.5, "planar": true, "sensor_property": "cell"})";
  job.map_name = "Bern map (v2) ü.geojson";
  job.sensors_name = "sensors \"final\".csv";
  job.created_ms = 1764000000123;
  job.started_ms = 1764000000456;
  job.finished_ms = 1764000009999;
  job.attempts = 2;
  return job;
}

TEST(JobStore, EveryFieldComesBackAsStored) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  const Job job = job_with_every_field();
  ASSERT_EQ(job.error->where.size(), 16u);  // the NUL byte is in the test's text
  store.insert(job);
  EXPECT_EQ(store.get(job.id), job);

  Job plain = queued_job(5);  // no error, empty summary and sensors
  store.insert(plain);
  EXPECT_EQ(store.get(plain.id), plain);
  EXPECT_FALSE(store.get(plain.id)->error.has_value());
}

TEST(JobStore, UnknownAndInvalidIdsAreNotFound) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  EXPECT_EQ(store.get(new_job_id()), std::nullopt);
  EXPECT_EQ(store.get("../etc/passwd"), std::nullopt);
  EXPECT_FALSE(store.cancel(new_job_id(), 1));
  EXPECT_FALSE(store.remove(new_job_id()));
  EXPECT_FALSE(store.set_progress(new_job_id(), 0.5, "x"));
}

TEST(JobStore, InsertRefusesBadIdsDuplicatesAndBadProgress) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  Job job = queued_job(1);
  store.insert(job);
  try {
    store.insert(job);
    FAIL() << "a second job with the same id was stored";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(folder.database().string()), std::string::npos) << message;
    EXPECT_NE(message.find("insert job " + job.id), std::string::npos) << message;
    EXPECT_NE(message.find("UNIQUE"), std::string::npos) << message;
  }
  Job bad_id = queued_job(1);
  bad_id.id = "../x";
  EXPECT_THROW(store.insert(bad_id), std::invalid_argument);
  Job bad_progress = queued_job(1);
  bad_progress.progress = 1.5;
  EXPECT_THROW(store.insert(bad_progress), std::invalid_argument);
  EXPECT_EQ(store.list(10).size(), 1u);
}

// Newest first by creation time, ties by id, against an independent sort of what was inserted.
TEST(JobStore, ListIsNewestFirstAndLimited) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  std::vector<Job> jobs;
  for (const std::int64_t created : {30, 10, 20, 20, 40, 10, 20, 50}) {
    jobs.push_back(queued_job(created));
    store.insert(jobs.back());
  }
  std::sort(jobs.begin(), jobs.end(), [](const Job& a, const Job& b) {
    return a.created_ms != b.created_ms ? a.created_ms > b.created_ms : a.id > b.id;
  });
  EXPECT_EQ(store.list(100), jobs);
  EXPECT_EQ(store.list(3), std::vector<Job>(jobs.begin(), jobs.begin() + 3));
  EXPECT_TRUE(store.list(0).empty());
}

TEST(JobStore, CountsByStatus) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  for (int i = 0; i < 5; ++i) store.insert(queued_job(i));
  ASSERT_TRUE(store.claim_next_queued(100));
  const std::optional<Job> second = store.claim_next_queued(100);
  ASSERT_TRUE(second);
  ASSERT_TRUE(store.finish(second->id, JobStatus::kDone, std::nullopt, "{}", 200));
  EXPECT_EQ(store.count_with_status(JobStatus::kQueued), 3u);
  EXPECT_EQ(store.count_with_status(JobStatus::kRunning), 1u);
  EXPECT_EQ(store.count_with_status(JobStatus::kDone), 1u);
  EXPECT_EQ(store.count_with_status(JobStatus::kFailed), 0u);
  EXPECT_EQ(store.count_with_status(JobStatus::kCancelled), 0u);
}

TEST(JobStore, ClaimTakesTheOldestQueuedJob) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  EXPECT_EQ(store.claim_next_queued(1), std::nullopt);
  Job newer = queued_job(200);
  Job older = queued_job(100);
  Job running = queued_job(50);
  running.status = JobStatus::kRunning;
  for (const Job& job : {newer, older, running}) store.insert(job);

  const std::optional<Job> claimed = store.claim_next_queued(777);
  ASSERT_TRUE(claimed);
  Job expected = older;
  expected.status = JobStatus::kRunning;
  expected.started_ms = 777;
  expected.attempts = 1;
  EXPECT_EQ(claimed, expected);
  EXPECT_EQ(store.get(older.id), expected);
  EXPECT_EQ(store.claim_next_queued(778)->id, newer.id);
  EXPECT_EQ(store.claim_next_queued(779), std::nullopt);
}

// Several workers take jobs at once, record progress and finish them; every job is taken exactly
// once and no write fails on a lock. `shared` workers use one
// store (one connection, the mutex); otherwise each opens its own, as worker processes would.
void claim_from_threads(bool shared) {
  constexpr int kJobs = 300;
  constexpr int kWorkers = 4;
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  for (int i = 0; i < kJobs; ++i) store.insert(queued_job(i % 7));  // ties in created_ms too

  std::mutex mutex;
  std::map<std::string, int> times_claimed;
  std::vector<std::thread> workers;
  for (int w = 0; w < kWorkers; ++w) {
    workers.emplace_back([&, w] {
      std::optional<JobStore> own;
      if (!shared) own.emplace(JobStore::open(folder.database()));
      JobStore& mine = shared ? store : *own;
      while (const std::optional<Job> job = mine.claim_next_queued(w)) {
        {
          const std::lock_guard<std::mutex> lock(mutex);
          ++times_claimed[job->id];
        }
        // The other writes of a worker, racing with the other connections' claims.
        if (!mine.set_progress(job->id, 0.5, "working") ||
            !mine.finish(job->id, JobStatus::kDone, std::nullopt, "{}", w)) {
          ADD_FAILURE() << "job " << job->id << " was not this worker's to finish";
        }
      }
    });
  }
  for (std::thread& worker : workers) worker.join();

  EXPECT_EQ(times_claimed.size(), static_cast<std::size_t>(kJobs));
  for (const auto& [id, times] : times_claimed) EXPECT_EQ(times, 1) << id;
  EXPECT_EQ(store.count_with_status(JobStatus::kDone), static_cast<std::size_t>(kJobs));
  EXPECT_EQ(store.count_with_status(JobStatus::kQueued), 0u);
}

TEST(JobStore, ThreadsSharingAStoreNeverClaimAJobTwice) { claim_from_threads(true); }
TEST(JobStore, ConnectionsOfTheirOwnNeverClaimAJobTwice) { claim_from_threads(false); }

TEST(JobStore, ProgressIsRecordedOnlyWhileRunning) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  const Job queued = queued_job(1);
  store.insert(queued);
  EXPECT_FALSE(store.set_progress(queued.id, 0.5, "too early"));
  EXPECT_EQ(store.get(queued.id), queued);

  const Job running = *store.claim_next_queued(2);
  EXPECT_TRUE(store.set_progress(running.id, 0.25, "cleaning the map"));
  EXPECT_EQ(store.get(running.id)->progress, 0.25);
  EXPECT_EQ(store.get(running.id)->stage, "cleaning the map");
  EXPECT_THROW(store.set_progress(running.id, -0.1, "x"), std::invalid_argument);
  EXPECT_THROW(store.set_progress(running.id, std::nan(""), "x"), std::invalid_argument);

  ASSERT_TRUE(store.cancel(running.id, 3));
  EXPECT_FALSE(store.set_progress(running.id, 0.5, "after the cancel"));
  EXPECT_EQ(store.get(running.id)->stage, "cleaning the map");
}

TEST(JobStore, FinishStoresTheOutcomeOnce) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  store.insert(queued_job(1));
  store.insert(queued_job(2));
  const Job first = *store.claim_next_queued(10);
  const Job second = *store.claim_next_queued(11);
  store.set_progress(first.id, 0.9, "writing reports");

  EXPECT_THROW(store.finish(first.id, JobStatus::kRunning, std::nullopt, "", 20), std::invalid_argument);
  ASSERT_TRUE(store.finish(first.id, JobStatus::kDone, std::nullopt, R"({"ok": true})", 20));
  Job done = *store.get(first.id);
  EXPECT_EQ(done.status, JobStatus::kDone);
  EXPECT_EQ(done.progress, 1.0);
  EXPECT_EQ(done.summary_json, R"({"ok": true})");
  EXPECT_EQ(done.finished_ms, 20);
  EXPECT_EQ(done.started_ms, 10);
  // A finished job stays as it is.
  EXPECT_FALSE(store.finish(first.id, JobStatus::kFailed, JobError{"x", "y", "z"}, "", 30));
  EXPECT_FALSE(store.cancel(first.id, 30));
  EXPECT_EQ(store.get(first.id), done);

  const JobError error{"worker_crashed", "the worker stopped on signal 11", "stage: fitting"};
  ASSERT_TRUE(store.finish(second.id, JobStatus::kFailed, error, "", 21));
  EXPECT_EQ(store.get(second.id)->status, JobStatus::kFailed);
  EXPECT_EQ(store.get(second.id)->error, error);
  EXPECT_EQ(store.get(second.id)->progress, 0.0);
}

TEST(JobStore, CancelStandsAgainstALateFinish) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  const Job queued = queued_job(1);
  store.insert(queued);
  EXPECT_TRUE(store.cancel(queued.id, 5));
  EXPECT_EQ(store.get(queued.id)->status, JobStatus::kCancelled);
  EXPECT_EQ(store.get(queued.id)->finished_ms, 5);
  EXPECT_EQ(store.claim_next_queued(6), std::nullopt);

  store.insert(queued_job(2));
  const Job running = *store.claim_next_queued(7);
  EXPECT_TRUE(store.cancel(running.id, 8));
  EXPECT_FALSE(store.cancel(running.id, 9));
  EXPECT_FALSE(store.finish(running.id, JobStatus::kDone, std::nullopt, "{}", 10));
  EXPECT_EQ(store.get(running.id)->status, JobStatus::kCancelled);
  EXPECT_EQ(store.get(running.id)->summary_json, "");
}

TEST(JobStore, RemoveDeletesTheRowOnly) {
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  const Job kept = queued_job(1);
  const Job removed = queued_job(2);
  store.insert(kept);
  store.insert(removed);
  EXPECT_TRUE(store.remove(removed.id));
  EXPECT_EQ(store.get(removed.id), std::nullopt);
  EXPECT_FALSE(store.remove(removed.id));
  EXPECT_EQ(store.list(10), std::vector<Job>{kept});
}

// What a server wrote is there after it is gone and a new one opens the file.
TEST(JobStore, EverythingSurvivesClosingAndReopening) {
  ScratchFolder folder;
  std::vector<Job> before;
  {
    JobStore store = JobStore::open(folder.database());
    store.insert(job_with_every_field());
    for (int i = 0; i < 4; ++i) store.insert(queued_job(10 + i));
    const Job done = *store.claim_next_queued(20);
    store.finish(done.id, JobStatus::kDone, std::nullopt, R"({"verdict": "mwvd"})", 21);
    const Job running = *store.claim_next_queued(22);
    store.set_progress(running.id, 0.5, "fitting");
    store.cancel(store.claim_next_queued(23)->id, 24);
    before = store.list(100);
    ASSERT_EQ(before.size(), 5u);
  }
  JobStore reopened = JobStore::open(folder.database());
  EXPECT_EQ(reopened.list(100), before);
}

// Servers and workers starting together on a new data folder: each open either creates the schema
// or finds it complete; none refuses the file as somebody else's or fails on a lock.
TEST(JobStore, ManyConnectionsOpeningANewFileAtOnceAllSucceed) {
  constexpr int kOpeners = 8;
  ScratchFolder folder;
  std::vector<std::thread> openers;
  std::mutex mutex;
  std::vector<std::string> failures;
  for (int i = 0; i < kOpeners; ++i) {
    openers.emplace_back([&] {
      try {
        JobStore::open(folder.database()).insert(queued_job(1));
      } catch (const std::exception& e) {
        const std::lock_guard<std::mutex> lock(mutex);
        failures.push_back(e.what());
      }
    });
  }
  for (std::thread& opener : openers) opener.join();
  EXPECT_TRUE(failures.empty()) << failures.front();
  EXPECT_EQ(JobStore::open(folder.database()).list(100).size(), static_cast<std::size_t>(kOpeners));
}

TEST(JobStore, TwoStoresOnOneFileSeeEachOthersWrites) {
  ScratchFolder folder;
  JobStore server = JobStore::open(folder.database());
  JobStore worker = JobStore::open(folder.database());
  server.insert(queued_job(1));
  const Job claimed = *worker.claim_next_queued(2);
  EXPECT_EQ(server.get(claimed.id)->status, JobStatus::kRunning);
  EXPECT_TRUE(server.cancel(claimed.id, 3));
  EXPECT_FALSE(worker.set_progress(claimed.id, 0.5, "x"));
}

// A job interrupted while running is queued again until it has had max_attempts, then failed with
// the reason; jobs in other states are left alone.
TEST(JobStore, RecoveryRequeuesThenFailsAnInterruptedJob) {
  ScratchFolder folder;
  constexpr int kMaxAttempts = 3;
  JobStore store = JobStore::open(folder.database());
  const Job job = queued_job(1);
  store.insert(job);
  const Job waiting = queued_job(2);
  store.insert(waiting);
  Job done = queued_job(0);
  done.status = JobStatus::kDone;
  done.finished_ms = 9;
  store.insert(done);

  for (int attempt = 1; attempt <= kMaxAttempts; ++attempt) {
    const Job running = *store.claim_next_queued(100 * attempt);
    ASSERT_EQ(running.id, job.id);
    EXPECT_EQ(running.attempts, attempt);
    store.set_progress(job.id, 0.6, "fitting sites");
    const RecoveryReport report = store.recover_interrupted(kMaxAttempts, 100 * attempt + 50);
    if (attempt < kMaxAttempts) {
      EXPECT_EQ(report.requeued, std::vector<std::string>{job.id});
      EXPECT_TRUE(report.failed.empty());
      const Job requeued = *store.get(job.id);
      EXPECT_EQ(requeued.status, JobStatus::kQueued);
      EXPECT_EQ(requeued.progress, 0.0);
      EXPECT_EQ(requeued.stage, kRequeuedStage);
      EXPECT_EQ(requeued.attempts, attempt);
      EXPECT_EQ(requeued.started_ms, 0);
      EXPECT_FALSE(requeued.error);
    } else {
      EXPECT_TRUE(report.requeued.empty());
      EXPECT_EQ(report.failed, std::vector<std::string>{job.id});
    }
  }
  const Job failed = *store.get(job.id);
  EXPECT_EQ(failed.status, JobStatus::kFailed);
  EXPECT_EQ(failed.finished_ms, 100 * kMaxAttempts + 50);
  ASSERT_TRUE(failed.error);
  EXPECT_EQ(failed.error->code, "interrupted");
  EXPECT_NE(failed.error->message.find("interrupted 3 times"), std::string::npos) << failed.error->message;
  EXPECT_NE(failed.error->where.find("fitting sites"), std::string::npos) << failed.error->where;
  EXPECT_EQ(store.count_with_status(JobStatus::kRunning), 0u);
  EXPECT_EQ(store.get(waiting.id), waiting);
  EXPECT_EQ(store.get(done.id), done);
  // Nothing left to recover.
  const RecoveryReport again = store.recover_interrupted(kMaxAttempts, 999);
  EXPECT_TRUE(again.requeued.empty() && again.failed.empty());
  EXPECT_THROW(store.recover_interrupted(0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace covmap::service
