// covmap::service internal: the job store's schema and connection settings, applied on open.
//
// prepare_job_schema(db): sets busy_timeout, checks PRAGMA user_version, switches to the WAL
// journal with synchronous=NORMAL, and creates the `jobs` table and its indexes in a fresh file.
// A file of a newer schema version, or a SQLite file with other tables and no version, is refused
// (std::runtime_error) before anything in it is changed.
//
// The table keeps one row per job; the status column holds job_status_name's text (a CHECK lists
// exactly those names), the error columns are all NULL or all set.
#pragma once

#include <string_view>

#include "service/sqlite_db.h"

namespace covmap::service {

// The columns of a job row, in the order job_from_row reads them and job inserts bind them.
inline constexpr std::string_view kJobColumns =
    "id, status, progress, stage, error_code, error_message, error_where, summary_json, options_json, "
    "map_name, sensors_name, created_ms, started_ms, finished_ms, attempts";

void prepare_job_schema(const sqlite::Database& db);

}  // namespace covmap::service
