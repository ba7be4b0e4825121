// The CSV syntax for site lists: a header line naming the columns, then one site per line; lines,
// delimiters (comma, semicolon, tab or '|'), quoting and decimal commas as io/csv_fields.h reads them.
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <optional>

#include "io/csv_fields.h"
#include "io/site_parsers.h"
#include "io/site_validation.h"
#include "io/text_util.h"

namespace covmap::io::detail {
namespace {

constexpr std::array<std::string_view, 4> kColumns = {"id", "x", "y", "weight"};
// An optional column: a name for people (labels in pictures); absent or empty: no name.
constexpr std::string_view kNameColumn = "name";

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// A number field; nullopt plus a message when it is not a number. Non-finite spellings ("inf",
// "nan") parse, so the value checks can say "must be finite" instead of "not a number".
std::optional<double> parse_number(std::string_view field, std::string_view name, std::string& error) {
  if (field.empty()) {
    error = std::string(name) + " is empty";
    return std::nullopt;
  }
  std::string_view digits = field;
  if (digits.front() == '+') digits.remove_prefix(1);  // from_chars rejects '+', people write it
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range) {
    error = std::string(name) + " is out of the range of a double (got '" + std::string(field) + "')";
    return std::nullopt;
  }
  if (ec != std::errc() || end != digits.data() + digits.size()) {
    error = std::string(name) + " is not a number (got '" + std::string(field) + "')";
    return std::nullopt;
  }
  return value;
}

// Where the header names `column` (case-insensitively): the field indices, in order.
std::vector<std::size_t> columns_named(const std::vector<std::string>& header, std::string_view column) {
  std::vector<std::size_t> found;
  for (std::size_t f = 0; f < header.size(); ++f)
    if (lower(header[f]) == column) found.push_back(f);
  return found;
}

}  // namespace

SiteTable parse_sites_csv(std::string_view text, const std::string& file) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark

  std::optional<std::array<std::size_t, 4>> column;  // index of id, x, y, weight; set by the header
  std::optional<std::size_t> name_column;            // index of the optional name column
  std::vector<SiteDraft> drafts;
  CsvDelimiter delimiter = CsvDelimiter::kComma;  // set by the header (io/csv_fields.h)
  int line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#') continue;

    if (!column) delimiter = detect_delimiter(line);
    const CsvFields fields = split_csv_line(line, delimiter);
    if (!column) {
      if (!fields.error.empty()) throw InputError(file, line_number, "header", fields.error);
      std::array<std::size_t, 4> found{};
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        const auto at = columns_named(fields.values, kColumns[c]);
        if (at.size() != 1) {
          throw InputError(file, line_number, "header",
                           std::string(at.empty() ? "missing" : "repeated") + " column '" + std::string(kColumns[c]) +
                               "' (the header must name id, x, y and weight once each, in any order)");
        }
        found[c] = at.front();
      }
      column = found;
      const auto names = columns_named(fields.values, kNameColumn);
      if (names.size() > 1)
        throw InputError(file, line_number, "header", "repeated column 'name' (name is optional, but at most once)");
      if (!names.empty()) name_column = names.front();
      continue;
    }

    SiteDraft draft;
    draft.line = line_number;
    draft.origin = "line " + std::to_string(line_number);
    if (!fields.error.empty()) {
      draft.problems.push_back(fields.error);
      drafts.push_back(std::move(draft));
      continue;
    }
    const auto field = [&](std::size_t c) -> const std::string* {
      const std::size_t f = (*column)[c];
      return f < fields.values.size() ? &fields.values[f] : nullptr;
    };
    if (const auto* id = field(0); id && !id->empty()) draft.site.id = *id;
    std::array<double*, 4> targets = {nullptr, &draft.site.x, &draft.site.y, &draft.site.weight};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      const std::string* value = field(c);
      if (!value) {
        draft.problems.push_back("missing " + std::string(kColumns[c]) + " (the row has " +
                                 std::to_string(fields.values.size()) + " fields)");
        continue;
      }
      if (c == 0) {
        if (value->empty()) draft.problems.push_back("id is empty");
        else if (!valid_utf8(*value)) draft.problems.push_back("id is not valid UTF-8");
        continue;
      }
      std::string error;
      if (const auto number = parse_number(number_text(*value, delimiter), kColumns[c], error)) {
        *targets[c] = *number;
      } else {
        draft.problems.push_back(error);
      }
    }
    // A row shorter than the header has no name: the name is optional, so that is no problem.
    if (name_column && *name_column < fields.values.size()) {
      if (valid_utf8(fields.values[*name_column])) draft.site.name = fields.values[*name_column];
      else draft.problems.push_back("name is not valid UTF-8");
    }
    if (draft.usable()) check_site_values(draft);
    drafts.push_back(std::move(draft));
  }
  if (!column) throw InputError(file, 0, "", "no header line (expected a line like: id,x,y,weight)");
  return finish_sites(std::move(drafts), file);
}

}  // namespace covmap::io::detail
