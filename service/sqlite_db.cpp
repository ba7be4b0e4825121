#include "service/sqlite_db.h"

#include <sqlite3.h>

#include <climits>
#include <string>
#include <system_error>

namespace covmap::service::sqlite {
namespace {

// SQLite takes lengths as int; a text longer than that cannot be bound (and is far above anything
// the service stores).
int text_length(const Database& db, std::string_view text, std::string_view operation) {
  if (text.size() > static_cast<std::size_t>(INT_MAX)) {
    throw db.error(operation, "a text of " + std::to_string(text.size()) + " bytes is too long to store");
  }
  return static_cast<int>(text.size());
}

}  // namespace

Database::Database(const std::filesystem::path& file) : file_(file) {
  const int flags = SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX;
  if (sqlite3_open_v2(file.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    // Even on failure SQLite usually returns a handle that carries the message; it must be closed.
    const std::runtime_error failure = db_ ? error("open") : error("open", "out of memory");
    sqlite3_close(db_);
    db_ = nullptr;
    throw failure;
  }
  sqlite3_extended_result_codes(db_, 1);
}

Database::~Database() { sqlite3_close(db_); }

void Database::exec(std::string_view sql, std::string_view operation) const {
  const std::string text(sql);
  if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK) throw error(operation);
}

bool Database::exec_unless_busy(std::string_view sql, std::string_view operation) const {
  const std::string text(sql);
  const int result = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, nullptr);
  if (result == SQLITE_OK) return true;
  // Extended result codes are on: the primary code is the low byte.
  if ((result & 0xff) == SQLITE_BUSY) return false;
  throw error(operation);
}

int Database::changes() const { return sqlite3_changes(db_); }

std::runtime_error Database::error(std::string_view operation) const {
  if (!db_) return error(operation, "no connection");
  std::string message = sqlite3_errmsg(db_);
  // SQLite says "disk I/O error" or "unable to open database file"; the system's reason ("No space
  // left on device", "Permission denied") is what the person running the server can act on.
  const int primary = sqlite3_extended_errcode(db_) & 0xff;
  const int system = sqlite3_system_errno(db_);
  if (system != 0 && (primary == SQLITE_IOERR || primary == SQLITE_FULL || primary == SQLITE_CANTOPEN)) {
    message += " (" + std::error_code(system, std::generic_category()).message() + ")";
  }
  return error(operation, message);
}

std::runtime_error Database::error(std::string_view operation, std::string_view message) const {
  return std::runtime_error("job store " + file_.string() + ": " + std::string(operation) + ": " +
                            std::string(message));
}

Statement::Statement(const Database& db, std::string_view sql, std::string operation)
    : db_(db), operation_(std::move(operation)) {
  if (sqlite3_prepare_v2(db.handle(), sql.data(), text_length(db, sql, operation_), &statement_, nullptr) !=
      SQLITE_OK) {
    throw db.error(operation_);
  }
}

Statement::~Statement() { sqlite3_finalize(statement_); }

Statement& Statement::bind(int index, std::string_view text) {
  // SQLITE_TRANSIENT: SQLite copies the text, so the caller's buffer may go away before step().
  // A null pointer would bind SQL NULL: an empty view (which may have none) binds "" instead.
  const char* bytes = text.empty() ? "" : text.data();
  if (sqlite3_bind_text(statement_, index, bytes, text_length(db_, text, operation_), SQLITE_TRANSIENT) != SQLITE_OK) {
    throw db_.error(operation_);
  }
  return *this;
}

Statement& Statement::bind(int index, std::int64_t value) {
  if (sqlite3_bind_int64(statement_, index, value) != SQLITE_OK) throw db_.error(operation_);
  return *this;
}

Statement& Statement::bind(int index, double value) {
  if (sqlite3_bind_double(statement_, index, value) != SQLITE_OK) throw db_.error(operation_);
  return *this;
}

Statement& Statement::bind_null(int index) {
  if (sqlite3_bind_null(statement_, index) != SQLITE_OK) throw db_.error(operation_);
  return *this;
}

bool Statement::step() {
  switch (sqlite3_step(statement_)) {
    case SQLITE_ROW: return true;
    case SQLITE_DONE: return false;
    default: throw db_.error(operation_);
  }
}

void Statement::run() {
  while (step()) {
  }
}

std::string Statement::text(int column) const { return optional_text(column).value_or(std::string()); }

std::optional<std::string> Statement::optional_text(int column) const {
  if (sqlite3_column_type(statement_, column) == SQLITE_NULL) return std::nullopt;
  // text first, then bytes: SQLite's documented order for a correct length.
  const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(statement_, column));
  const int bytes = sqlite3_column_bytes(statement_, column);
  if (text == nullptr) return std::string();
  return std::string(text, static_cast<std::size_t>(bytes));
}

std::int64_t Statement::integer(int column) const { return sqlite3_column_int64(statement_, column); }

double Statement::real(int column) const { return sqlite3_column_double(statement_, column); }

Transaction::Transaction(const Database& db, std::string operation) : db_(db), operation_(std::move(operation)) {
  db_.exec("BEGIN IMMEDIATE", operation_);
  open_ = true;
}

Transaction::~Transaction() {
  // Best effort: a failed rollback leaves SQLite to roll the journal back when next opened.
  if (open_) sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void Transaction::commit() {
  db_.exec("COMMIT", operation_);
  open_ = false;
}

}  // namespace covmap::service::sqlite
