#include "io/csv_fields.h"

#include <algorithm>
#include <array>
#include <cctype>


namespace covmap::io::detail {
namespace {

constexpr std::array<CsvDelimiter, 4> kCandidates = {CsvDelimiter::kComma, CsvDelimiter::kSemicolon, CsvDelimiter::kTab,
                                                     CsvDelimiter::kPipe};

// Delimiters outside double quotes.
std::size_t count_outside_quotes(std::string_view line, char delimiter) {
  std::size_t n = 0;
  bool quoted = false;
  for (const char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == delimiter && !quoted) ++n;
  }
  return n;
}

bool blank(char c, CsvDelimiter d) { return c == ' ' || c == '\r' || (c == '\t' && d != CsvDelimiter::kTab); }

std::string_view trim_blanks(std::string_view s, CsvDelimiter d) {
  while (!s.empty() && blank(s.front(), d)) s.remove_prefix(1);
  while (!s.empty() && blank(s.back(), d)) s.remove_suffix(1);
  return s;
}

}  // namespace

CsvDelimiter detect_delimiter(std::string_view header_line) {
  CsvDelimiter best = CsvDelimiter::kComma;
  std::size_t most = count_outside_quotes(header_line, ',');
  for (const CsvDelimiter d : kCandidates) {
    const std::size_t n = count_outside_quotes(header_line, static_cast<char>(d));
    if (n > most) most = n, best = d;
  }
  return best;
}

std::string_view delimiter_name(CsvDelimiter delimiter) {
  switch (delimiter) {
    case CsvDelimiter::kComma: return "comma";
    case CsvDelimiter::kSemicolon: return "semicolon";
    case CsvDelimiter::kTab: return "tab";
    case CsvDelimiter::kPipe: return "'|'";
  }
  return "comma";
}

CsvFields split_csv_line(std::string_view line, CsvDelimiter delimiter) {
  const char sep = static_cast<char>(delimiter);
  CsvFields out;
  std::size_t i = 0;
  while (true) {
    while (i < line.size() && blank(line[i], delimiter)) ++i;
    std::string field;
    if (i < line.size() && line[i] == '"') {
      bool closed = false;
      for (++i; i < line.size(); ++i) {
        if (line[i] != '"') {
          field += line[i];
        } else if (i + 1 < line.size() && line[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          closed = true;
          ++i;
          break;
        }
      }
      if (!closed) {
        out.error = "unterminated quoted field";
        return out;
      }
      while (i < line.size() && blank(line[i], delimiter)) ++i;
      if (i < line.size() && line[i] != sep) {
        out.error = "unexpected text after a quoted field";
        return out;
      }
    } else {
      const std::size_t end = std::min(line.find(sep, i), line.size());
      field = std::string(trim_blanks(line.substr(i, end - i), delimiter));
      i = end;
    }
    out.values.push_back(std::move(field));
    if (i >= line.size()) return out;
    ++i;  // the delimiter
  }
}

std::string number_text(std::string_view field, CsvDelimiter delimiter) {
  std::string text(field);
  if (delimiter == CsvDelimiter::kComma || std::count(text.begin(), text.end(), ',') != 1 ||
      text.find('.') != std::string::npos)
    return text;
  const bool numeric = std::all_of(text.begin(), text.end(), [](unsigned char c) {
    return std::isdigit(c) || c == ',' || c == '-' || c == '+' || c == 'e' || c == 'E';
  });
  if (numeric) std::replace(text.begin(), text.end(), ',', '.');
  return text;
}

}  // namespace covmap::io::detail
