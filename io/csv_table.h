// covmap::io CSV tables: the one reading of covmap's CSV files (site lists, reported sensors, the
// map generator's lon/lat town lists), each caller naming the columns it reads.
//
// Accepted: text of lines ending in '\n' (a '\r' before it is ignored) with an optional UTF-8 byte
// order mark; blank lines and lines starting with '#' are skipped; the first other line is the
// header. The header names columns in any order and any case; columns the caller does not name are
// ignored. The delimiter is the one of comma, semicolon, tab and '|' that splits the header into
// the most fields (a comma when none does); fields are trimmed and may be double-quoted ("" is a
// quote inside); with any delimiter but the comma, a number may be written with a decimal comma.
// Guaranteed: a required column is named exactly once and an optional one at most once; rows come
// in file order, each with its 1-based line number.
// Rejected with InputError: no header line (line 0), a header that cannot be split, a required
// column missing or repeated, an optional column repeated (each at the header's line, item
// "header"). A row that cannot be split is not an error here: it comes with CsvRow::error set, so
// the caller reports it beside the other rows' problems.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace covmap::io {

struct CsvColumn {
  std::string_view name;           // lower case; the header may write it in any case
  bool required = false;           // the header must name it exactly once (otherwise at most once)
  std::string_view repeated_note;  // an optional column's hint in its "repeated column" message
};

class CsvTable;

// One data line. Fields are addressed by the index of their column in the caller's column list.
struct CsvRow {
  int line = 0;                     // 1-based
  std::vector<std::string> values;  // the line's fields in file order
  std::string error;                // non-empty when the line could not be split (values unusable)

  // The field of column c: nullptr when the header does not name it or this row is shorter.
  const std::string* field(std::size_t c) const;
  // "missing x (the row has 2 fields)": for a required field the row lacks.
  std::string missing(std::size_t c) const;
  // The field of column c (which must exist) as a number, or nullopt with `error` saying why
  // ("x is empty", "x is not a number (got 'a')", "x is out of the range of a double (got ...)").
  // "inf" and "nan" parse, so value checks can say "must be finite" rather than "not a number".
  std::optional<double> number(std::size_t c, std::string& error) const;

 private:
  friend class CsvTable;
  const CsvTable* table_ = nullptr;
};

class CsvTable {
 public:
  // Reads up to and including the header. `text` and `columns` must outlive the table; `file`
  // names it in messages; `example` is a header line for the message when there is none
  // ("id,x,y,weight").
  CsvTable(std::string_view text, std::string file, std::span<const CsvColumn> columns, std::string_view example);

  // Whether the header names column c.
  bool has(std::size_t c) const { return position_[c] != kAbsent; }
  const std::string& file() const { return file_; }
  int header_line() const { return header_line_; }

  // The next data line into `row`; false at the end of the text.
  bool next(CsvRow& row);

 private:
  friend struct CsvRow;
  static constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);

  std::string_view text_;
  std::size_t pos_ = 0;
  int line_number_ = 0;
  int header_line_ = 0;
  std::string file_;
  std::span<const CsvColumn> columns_;
  std::vector<std::size_t> position_;  // per column, its field index or kAbsent
  char delimiter_ = ',';

  // The next line that is neither blank nor a comment, trimmed; false at the end.
  bool next_line(std::string_view& line);
};

}  // namespace covmap::io
