// covmap::service internal: a thin owner of one SQLite connection and its statements, so that the
// job store reads as SQL and every failure becomes one std::runtime_error of the same shape:
//   "job store <file>: <operation>: <sqlite3_errmsg> [(<the system's reason>)]"
// Not thread-safe by itself: JobStore serializes all use of a Database behind its mutex. sqlite3.h
// stays out of this header (the service links SQLite privately).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace covmap::service::sqlite {

class Database;

// One prepared statement. Parameters are numbered from 1, columns from 0, as in SQLite.
class Statement {
 public:
  Statement(const Database& db, std::string_view sql, std::string operation);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, double value);
  Statement& bind_null(int index);

  // Runs to the next row: true when one is ready to read, false when the statement is done.
  bool step();
  // Runs to the end, ignoring any rows.
  void run();

  std::string text(int column) const;  // NULL reads as ""
  std::optional<std::string> optional_text(int column) const;
  std::int64_t integer(int column) const;
  double real(int column) const;

 private:
  const Database& db_;
  sqlite3_stmt* statement_ = nullptr;
  std::string operation_;
};

class Database {
 public:
  // Opens (creating if missing) the database file; throws naming the file when it cannot.
  explicit Database(const std::filesystem::path& file);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  // Runs SQL without parameters or results (several statements allowed).
  void exec(std::string_view sql, std::string_view operation) const;
  // exec, except that SQLITE_BUSY returns false instead of throwing: for the statements SQLite runs
  // without calling the busy handler (a change of journal mode), which the caller retries.
  bool exec_unless_busy(std::string_view sql, std::string_view operation) const;
  // Rows changed by the last INSERT, UPDATE or DELETE.
  int changes() const;

  // The error for `operation` with SQLite's message for the last failure on this connection.
  std::runtime_error error(std::string_view operation) const;
  // An error for `operation` with a message of covmap's own.
  std::runtime_error error(std::string_view operation, std::string_view message) const;

  sqlite3* handle() const { return db_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  sqlite3* db_ = nullptr;
};

// BEGIN IMMEDIATE on construction: the write lock is taken before anything is read, so a
// read-then-write (take the oldest queued job) cannot interleave with another connection's.
// Rolled back on destruction unless commit() succeeded.
class Transaction {
 public:
  Transaction(const Database& db, std::string operation);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  const Database& db_;
  std::string operation_;
  bool open_ = false;
};

}  // namespace covmap::service::sqlite
