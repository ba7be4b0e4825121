#include "io/csv_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "io/csv_fields.h"
#include "io/input_error.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// "the header must name id, x, y and weight once each, in any order"
std::string required_rule(std::span<const CsvColumn> columns) {
  std::vector<std::string_view> names;
  for (const CsvColumn& c : columns)
    if (c.required) names.push_back(c.name);
  std::string list;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k > 0) list += k + 1 == names.size() ? " and " : ", ";
    list += names[k];
  }
  return "the header must name " + list + " once each, in any order";
}

}  // namespace

CsvTable::CsvTable(std::string_view text, std::string file, std::span<const CsvColumn> columns, std::string_view example)
    : text_(text), file_(std::move(file)), columns_(columns), position_(columns.size(), kAbsent) {
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") text_.remove_prefix(3);  // UTF-8 byte order mark
  std::string_view line;
  if (!next_line(line)) throw InputError(file_, 0, "", "no header line (expected a line like: " + std::string(example) + ")");
  header_line_ = line_number_;
  const auto delimiter = detail::detect_delimiter(line);
  delimiter_ = static_cast<char>(delimiter);
  const detail::CsvFields header = detail::split_csv_line(line, delimiter);
  if (!header.error.empty()) throw InputError(file_, line_number_, "header", header.error);
  std::vector<std::string> names;
  for (const std::string& f : header.values) names.push_back(lower(f));

  // Required columns first, in the caller's order; then repeated optional ones, in the header's.
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    if (!columns_[c].required) continue;
    const auto n = std::count(names.begin(), names.end(), columns_[c].name);
    if (n != 1) {
      throw InputError(file_, line_number_, "header",
                       std::string(n == 0 ? "missing" : "repeated") + " column '" + std::string(columns_[c].name) + "' (" +
                           required_rule(columns_) + ")");
    }
    position_[c] = static_cast<std::size_t>(std::find(names.begin(), names.end(), columns_[c].name) - names.begin());
  }
  for (std::size_t f = 0; f < names.size(); ++f) {
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (columns_[c].required || names[f] != columns_[c].name) continue;
      if (position_[c] != kAbsent) {
        const std::string_view note = columns_[c].repeated_note;
        throw InputError(file_, line_number_, "header",
                         "repeated column '" + std::string(columns_[c].name) + "'" +
                             (note.empty() ? std::string() : " (" + std::string(note) + ")"));
      }
      position_[c] = f;
    }
  }
}

bool CsvTable::next_line(std::string_view& line) {
  while (pos_ < text_.size()) {
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    line = detail::trim(text_.substr(pos_, end - pos_));
    pos_ = end + 1;
    ++line_number_;
    if (!line.empty() && line.front() != '#') return true;
  }
  return false;
}

bool CsvTable::next(CsvRow& row) {
  std::string_view line;
  if (!next_line(line)) return false;
  detail::CsvFields fields = detail::split_csv_line(line, static_cast<detail::CsvDelimiter>(delimiter_));
  row.line = line_number_;
  row.values = std::move(fields.values);
  row.error = std::move(fields.error);
  row.table_ = this;
  return true;
}

const std::string* CsvRow::field(std::size_t c) const {
  const std::size_t f = table_->position_[c];
  return f != CsvTable::kAbsent && f < values.size() ? &values[f] : nullptr;
}

std::string CsvRow::missing(std::size_t c) const {
  return "missing " + std::string(table_->columns_[c].name) + " (the row has " + std::to_string(values.size()) + " fields)";
}

std::optional<double> CsvRow::number(std::size_t c, std::string& error) const {
  const std::string_view name = table_->columns_[c].name;
  const std::string& field = *this->field(c);
  if (field.empty()) {
    error = std::string(name) + " is empty";
    return std::nullopt;
  }
  const std::string text = detail::number_text(field, static_cast<detail::CsvDelimiter>(table_->delimiter_));
  std::string_view digits = text;
  if (digits.front() == '+') digits.remove_prefix(1);  // from_chars rejects '+', people write it
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range) {
    error = std::string(name) + " is out of the range of a double (got '" + text + "')";
    return std::nullopt;
  }
  if (ec != std::errc() || end != digits.data() + digits.size()) {
    error = std::string(name) + " is not a number (got '" + text + "')";
    return std::nullopt;
  }
  return value;
}

}  // namespace covmap::io
