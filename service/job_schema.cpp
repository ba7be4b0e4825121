#include "service/job_schema.h"

#include <string>

#include "service/job.h"
#include "service/job_store.h"

namespace covmap::service {
namespace {

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

std::int64_t single_integer(const sqlite::Database& db, std::string_view sql, std::string operation) {
  sqlite::Statement query(db, sql, std::move(operation));
  return query.step() ? query.integer(0) : 0;
}

// Refuses a file this covmap must not touch: a newer schema, or somebody else's database.
void check_version(const sqlite::Database& db, std::int64_t version) {
  if (version > kJobStoreSchemaVersion) {
    throw db.error("open", "the job store was written by a newer covmap (schema version " + std::to_string(version) +
                               "; this covmap reads version " + std::to_string(kJobStoreSchemaVersion) +
                               " and older): run that covmap, or give this one another data folder");
  }
  if (version == 0 && single_integer(db, "SELECT count(*) FROM sqlite_schema", "open") > 0) {
    throw db.error("open", "the file is a SQLite database with other tables and no covmap job store in it: "
                           "give covmap a data folder of its own");
  }
}

}  // namespace

void prepare_job_schema(const sqlite::Database& db) {
  db.exec("PRAGMA busy_timeout = " + std::to_string(kJobStoreBusyTimeoutMs), "open");
  // Checked before anything is written, so that a refused file stays as it was.
  check_version(db, single_integer(db, "PRAGMA user_version", "read the schema version"));
  {
    sqlite::Statement journal(db, "PRAGMA journal_mode = WAL", "switch to the WAL journal");
    const std::string mode = journal.step() ? journal.text(0) : std::string();
    if (mode != "wal") {
      throw db.error("switch to the WAL journal",
                     "the journal mode stays '" + mode + "' (the file system may not support WAL's shared memory)");
    }
  }
  db.exec("PRAGMA synchronous = NORMAL", "open");
  // Another process may be creating the schema at the same moment: decide under the write lock.
  sqlite::Transaction transaction(db, "create the schema");
  const std::int64_t version = single_integer(db, "PRAGMA user_version", "read the schema version");
  check_version(db, version);
  if (version == 0) db.exec(create_schema_sql(), "create the schema");
  transaction.commit();
}

}  // namespace covmap::service
