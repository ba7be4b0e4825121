// The job store against the real failures of a server: a process killed with SIGKILL while it
// works on the database, and files it must not open.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "service/job_store.h"
#include "service/sqlite_db.h"  // internal: raw SQL, as another program would write the file
#include "service_test_util.h"

namespace covmap::service {
namespace {

using testing::queued_job;
using testing::ScratchFolder;

std::string single_text(const std::filesystem::path& file, const std::string& sql) {
  sqlite::Database db(file);
  sqlite::Statement query(db, sql, "test query");
  return query.step() ? query.text(0) : std::string();
}

// Runs `work` in a forked child, which writes one byte to `ready` when it reaches the point to be
// killed at; the parent waits for that byte (plus `linger`), kills the child with SIGKILL and
// reaps it. The child never returns into the test.
template <class Work>
void kill_child_when_ready(Work work, std::chrono::milliseconds linger) {
  int pipe_ends[2];
  ASSERT_EQ(::pipe(pipe_ends), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::close(pipe_ends[0]);
    try {
      work(pipe_ends[1]);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "child: %s\n", e.what());
      ::_exit(3);
    }
    ::_exit(4);  // work returned: it should have been killed first
  }
  ::close(pipe_ends[1]);
  char byte = 0;
  const ssize_t got = ::read(pipe_ends[0], &byte, 1);
  ::close(pipe_ends[0]);
  std::this_thread::sleep_for(linger);
  ::kill(pid, SIGKILL);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_EQ(got, 1) << "the child ended before it was ready (exit status " << WEXITSTATUS(status) << ")";
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the child was not the one to end it";
}

void signal_ready(int fd) {
  const char byte = 1;
  if (::write(fd, &byte, 1) != 1) ::_exit(5);
}

// A worker (or a server) in its own connection: takes the next job at time 10, which must be
// `expected_id`, says so on `ready`, and records progress in a loop until it is killed.
[[noreturn]] void claim_and_work_forever(const std::filesystem::path& file, const std::string& expected_id, int ready) {
  JobStore store = JobStore::open(file);
  const std::optional<Job> claimed = store.claim_next_queued(10);
  if (!claimed || claimed->id != expected_id) ::_exit(6);
  signal_ready(ready);
  for (long i = 0;; ++i) store.set_progress(expected_id, static_cast<double>(i % 1000) / 1000, "step " + std::to_string(i));
}

// The real crash: a worker process claims a job and is killed while it records progress in a
// loop. The parent opens the file, finds the job running with the attempt counted, and recovers it.
TEST(JobStoreCrash, AWorkerKilledMidJobLeavesARecoverableDatabase) {
  ScratchFolder folder;
  const Job job = queued_job(1);
  const Job other = queued_job(2);
  {
    JobStore store = JobStore::open(folder.database());
    store.insert(job);
    store.insert(other);
  }  // closed before the fork: a child must not use a connection it inherited
  kill_child_when_ready([&](int ready) { claim_and_work_forever(folder.database(), job.id, ready); },
                        std::chrono::milliseconds(50));

  JobStore store = JobStore::open(folder.database());
  EXPECT_EQ(single_text(folder.database(), "PRAGMA integrity_check"), "ok");
  const Job interrupted = *store.get(job.id);
  EXPECT_EQ(interrupted.status, JobStatus::kRunning);
  EXPECT_EQ(interrupted.attempts, 1);
  EXPECT_EQ(interrupted.started_ms, 10);
  EXPECT_GE(interrupted.progress, 0.0);
  EXPECT_LT(interrupted.progress, 1.0);
  EXPECT_EQ(store.get(other.id), other);

  const RecoveryReport report = store.recover_interrupted(2, 20);
  EXPECT_EQ(report.requeued, std::vector<std::string>{job.id});
  EXPECT_EQ(store.count_with_status(JobStatus::kRunning), 0u);
  const Job again = *store.claim_next_queued(30);
  EXPECT_EQ(again.id, job.id);
  EXPECT_EQ(again.attempts, 2);
}

// The server keeps its connection open while a worker process it forked is killed mid-job: the
// server's store goes on working and can fail the job with the reason.
TEST(JobStoreCrash, AServerOutlivesAKilledWorker) {
  ScratchFolder folder;
  JobStore server = JobStore::open(folder.database());
  const Job job = queued_job(1);
  server.insert(job);
  kill_child_when_ready([&](int ready) { claim_and_work_forever(folder.database(), job.id, ready); },
                        std::chrono::milliseconds(20));
  EXPECT_EQ(server.get(job.id)->status, JobStatus::kRunning);
  const JobError killed{"worker_killed", "the worker was killed by signal 9", ""};
  EXPECT_TRUE(server.finish(job.id, JobStatus::kFailed, killed, "", 40));
  EXPECT_EQ(server.get(job.id)->error, killed);
  server.insert(queued_job(2));
  EXPECT_EQ(server.count_with_status(JobStatus::kQueued), 1u);
  EXPECT_EQ(single_text(folder.database(), "PRAGMA integrity_check"), "ok");
}

// More than the ~4 MB of rows the doomed transaction writes could stay in its 2-page cache.
constexpr std::uintmax_t kSpilledBytes = 1'000'000;

// Killed inside a write transaction that has already spilled pages to the WAL: none of it counts.
TEST(JobStoreCrash, AProcessKilledInsideATransactionChangesNothing) {
  ScratchFolder folder;
  std::vector<Job> before;
  {
    JobStore store = JobStore::open(folder.database());
    for (int i = 0; i < 20; ++i) store.insert(queued_job(i));
    before = store.list(100);
  }
  kill_child_when_ready(
      [&](int ready) {
        JobStore::open(folder.database());  // as a server would, then raw writes
        sqlite::Database db(folder.database());
        db.exec("PRAGMA cache_size = 2", "small cache, so that pages reach the WAL before the commit");
        sqlite::Transaction transaction(db, "doomed");
        db.exec("UPDATE jobs SET status = 'done', summary_json = 'lost'", "doomed");
        db.exec("DELETE FROM jobs WHERE created_ms < 10", "doomed");
        db.exec("WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 FROM n WHERE i < 2000) "
                "INSERT INTO jobs SELECT printf('%032x', i), 'queued', 0, hex(zeroblob(1000)), NULL, NULL, NULL, '', '', "
                "'', '', i, 0, 0, 0 FROM n",
                "doomed");
        signal_ready(ready);
        ::pause();
      },
      std::chrono::milliseconds(0));

  // The uncommitted rows really were on disk, in the WAL, when the process died.
  const auto wal = std::filesystem::path(folder.database().string() + "-wal");
  EXPECT_GT(std::filesystem::file_size(wal), kSpilledBytes);
  JobStore store = JobStore::open(folder.database());
  EXPECT_EQ(single_text(folder.database(), "PRAGMA integrity_check"), "ok");
  EXPECT_EQ(store.list(10000), before);
}

// A full disk, simulated by a file-size limit (the writes past it fail with EFBIG as they would
// with ENOSPC): the insert fails naming the store and the operation, leaves no trace, and the
// same store works again once there is room.
TEST(JobStoreCrash, AFullDiskFailsOneWriteAndNothingElse) {
  constexpr rlim_t kFileSizeLimit = 256 * 1024;
  constexpr std::size_t kSummaryBytes = 4 * 1024 * 1024;
  ScratchFolder folder;
  JobStore store = JobStore::open(folder.database());
  const Job kept = queued_job(1);
  store.insert(kept);
  Job big = queued_job(2);
  big.summary_json = std::string(kSummaryBytes, 'x');

  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  rlimit small = old_limit;
  small.rlim_cur = kFileSizeLimit;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    store.insert(big);
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);

  EXPECT_NE(message.find(folder.database().string()), std::string::npos) << message;
  EXPECT_NE(message.find("insert job " + big.id), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;  // the system's reason
  EXPECT_EQ(store.get(big.id), std::nullopt);
  EXPECT_EQ(store.list(10), std::vector<Job>{kept});
  store.insert(big);
  EXPECT_EQ(store.get(big.id), big);
  EXPECT_EQ(single_text(folder.database(), "PRAGMA integrity_check"), "ok");
}

TEST(JobStoreCrash, ANewerSchemaIsRefusedAndLeftAsItWas) {
  ScratchFolder folder;
  JobStore::open(folder.database()).insert(queued_job(1));
  sqlite::Database(folder.database()).exec("PRAGMA user_version = 2", "test");
  try {
    JobStore::open(folder.database());
    FAIL() << "a database of a newer schema was opened";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(folder.database().string()), std::string::npos) << message;
    EXPECT_NE(message.find("newer covmap"), std::string::npos) << message;
    EXPECT_NE(message.find("schema version 2"), std::string::npos) << message;
  }
  EXPECT_EQ(single_text(folder.database(), "PRAGMA user_version"), "2");
  EXPECT_EQ(single_text(folder.database(), "SELECT count(*) FROM jobs"), "1");
}

TEST(JobStoreCrash, SomebodyElsesDatabaseIsRefused) {
  ScratchFolder folder;
  sqlite::Database(folder.database()).exec("CREATE TABLE photos (name TEXT)", "test");
  EXPECT_THROW(JobStore::open(folder.database()), std::runtime_error);
  EXPECT_EQ(single_text(folder.database(), "PRAGMA journal_mode"), "delete");  // not even switched to WAL
}

TEST(JobStoreCrash, AFileThatIsNotADatabaseIsRefusedByName) {
  ScratchFolder folder;
  std::ofstream(folder.database()) << "{\"jobs\": []}\n" << std::string(4096, 'x');
  try {
    JobStore::open(folder.database());
    FAIL() << "a text file was opened as a job store";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(folder.database().string()), std::string::npos) << message;
    EXPECT_NE(message.find("not a database"), std::string::npos) << message;
  }
}

TEST(JobStoreCrash, AMissingFolderIsRefusedByName) {
  ScratchFolder folder;
  const auto file = folder.path() / "no" / "such" / "jobs.sqlite";
  try {
    JobStore::open(file);
    FAIL() << "opened a database in a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace covmap::service
