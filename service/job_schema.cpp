#include "service/job_schema.h"

#include <chrono>
#include <string>
#include <thread>

#include "service/job.h"
#include "service/job_store.h"

namespace covmap::service {
namespace {

// How long to pause between attempts at a change SQLite will not wait for itself.
constexpr std::chrono::milliseconds kBusyRetryPause{5};

// "'queued', 'running', ...": the one spelling of the statuses, for the table's CHECK.
std::string status_name_list() {
  std::string list;
  for (const JobStatus status : kAllJobStatuses) {
    if (!list.empty()) list += ", ";
    list += '\'';
    list += job_status_name(status);
    list += '\'';
  }
  return list;
}

std::string create_schema_sql() {
  return "CREATE TABLE jobs ("
         "  id TEXT PRIMARY KEY NOT NULL,"
         "  status TEXT NOT NULL CHECK (status IN (" + status_name_list() + ")),"
         "  progress REAL NOT NULL,"
         "  stage TEXT NOT NULL,"
         "  error_code TEXT,"
         "  error_message TEXT,"
         "  error_where TEXT,"
         "  summary_json TEXT NOT NULL,"
         "  options_json TEXT NOT NULL,"
         "  map_name TEXT NOT NULL,"
         "  sensors_name TEXT NOT NULL,"
         "  created_ms INTEGER NOT NULL,"
         "  started_ms INTEGER NOT NULL,"
         "  finished_ms INTEGER NOT NULL,"
         "  attempts INTEGER NOT NULL"
         ") STRICT;"
         // claim_next_queued and count_with_status; list.
         "CREATE INDEX jobs_by_status ON jobs (status, created_ms, id);"
         "CREATE INDEX jobs_by_creation ON jobs (created_ms, id);"
         "PRAGMA user_version = " + std::to_string(kJobStoreSchemaVersion) + ";";
}

// What the file holds before covmap touches it: its schema version and how many tables, indexes
// and views it has. One statement, so one snapshot: another process creating the schema at the
// same moment is seen either before or after, never half-way.
struct FileState {
  std::int64_t version = 0;
  std::int64_t objects = 0;
};

FileState read_file_state(const sqlite::Database& db) {
  sqlite::Statement query(db, "SELECT (SELECT user_version FROM pragma_user_version), (SELECT count(*) FROM sqlite_schema)",
                          "read the schema version");
  FileState state;
  if (query.step()) state = FileState{query.integer(0), query.integer(1)};
  return state;
}

// Refuses a file this covmap must not touch: a newer schema, or somebody else's database.
void check_file_state(const sqlite::Database& db, const FileState& state) {
  if (state.version > kJobStoreSchemaVersion) {
    throw db.error("open", "the job store was written by a newer covmap (schema version " + std::to_string(state.version) +
                               "; this covmap reads version " + std::to_string(kJobStoreSchemaVersion) +
                               " and older): run that covmap, or give this one another data folder");
  }
  if (state.version == 0 && state.objects > 0) {
    throw db.error("open", "the file is a SQLite database with other tables and no covmap job store in it: "
                           "give covmap a data folder of its own");
  }
}

// The journal mode is changed under an exclusive lock for which SQLite does not wait (it answers
// "database is locked" at once when another connection is opening the same new file), so the
// change is retried here for as long as the busy timeout would have waited.
void switch_to_wal(const sqlite::Database& db) {
  const std::string operation = "switch to the WAL journal";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(kJobStoreBusyTimeoutMs);
  while (!db.exec_unless_busy("PRAGMA journal_mode = WAL", operation)) {
    if (std::chrono::steady_clock::now() > deadline) {
      throw db.error(operation, "the database stayed locked by another connection for " +
                                    std::to_string(kJobStoreBusyTimeoutMs) + " ms");
    }
    std::this_thread::sleep_for(kBusyRetryPause);
  }
  // Without WAL support (some network file systems) SQLite keeps the old mode and says so.
  sqlite::Statement journal(db, "PRAGMA journal_mode", operation);
  const std::string mode = journal.step() ? journal.text(0) : std::string();
  if (mode != "wal") {
    throw db.error(operation, "the journal mode stays '" + mode + "' (the file system may not support WAL's shared memory)");
  }
}

}  // namespace

void prepare_job_schema(const sqlite::Database& db) {
  db.exec("PRAGMA busy_timeout = " + std::to_string(kJobStoreBusyTimeoutMs), "open");
  // Checked before anything is written, so that a refused file stays as it was.
  check_file_state(db, read_file_state(db));
  switch_to_wal(db);
  db.exec("PRAGMA synchronous = NORMAL", "open");
  // Another process may be creating the schema at the same moment: decide under the write lock.
  sqlite::Transaction transaction(db, "create the schema");
  const FileState state = read_file_state(db);
  check_file_state(db, state);
  if (state.version == 0) db.exec(create_schema_sql(), "create the schema");
  transaction.commit();
}

}  // namespace covmap::service
