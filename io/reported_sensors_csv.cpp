// The CSV syntax for reported sensors: a header naming the columns, then one sensor per line.
// Lines, delimiters, quoting and numbers follow the sites CSV (io/csv_fields.h); the columns differ.
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>

#include "io/csv_fields.h"
#include "io/reported_sensors_parsers.h"
#include "io/text_util.h"

namespace covmap::io::detail {
namespace {

enum Column : std::size_t { kId, kName, kX, kY, kLon, kLat, kWeight, kPower, kPositionSigma, kPowerSigma, kColumnCount };
constexpr std::array<std::string_view, kColumnCount> kNames = {
    "id", "name", "x", "y", "lon", "lat", "weight", "tx_power_dbm", "position_sigma_m", "power_sigma_db"};
constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);

// A number, or nullopt with `error` set. "inf" and "nan" parse, so the value checks can say
// "must be finite" rather than "not a number".
std::optional<double> to_number(std::string_view field, std::string_view name, std::string& error) {
  std::string_view digits = field;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);  // from_chars rejects '+'
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range) {
    error = std::string(name) + " is out of the range of a double (got '" + std::string(field) + "')";
    return std::nullopt;
  }
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size()) {
    error = std::string(name) + " is not a number (got '" + std::string(field) + "')";
    return std::nullopt;
  }
  return value;
}

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

using ColumnIndex = std::array<std::size_t, kColumnCount>;

ColumnIndex read_header(const std::vector<std::string>& fields, const std::string& file, int line) {
  ColumnIndex at;
  at.fill(kAbsent);
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const auto it = std::find(kNames.begin(), kNames.end(), lower(fields[f]));
    if (it == kNames.end()) continue;  // other columns are the user's business
    const auto c = static_cast<std::size_t>(it - kNames.begin());
    if (at[c] != kAbsent) throw InputError(file, line, "header", "repeated column '" + std::string(kNames[c]) + "'");
    at[c] = f;
  }
  const auto has = [&](Column c) { return at[c] != kAbsent; };
  std::string missing;
  if (!has(kId)) missing = "an id column";
  // Both pairs are allowed (vendor exports give both); the map decides which one is used
  // (finish_sensors). Each pair that is started must be complete.
  const bool planar = has(kX) || has(kY), geographic = has(kLon) || has(kLat);
  if (planar && !(has(kX) && has(kY))) missing += std::string(missing.empty() ? "" : ", ") + "both x and y";
  if (geographic && !(has(kLon) && has(kLat))) missing += std::string(missing.empty() ? "" : ", ") + "both lon and lat";
  if (!planar && !geographic) missing += std::string(missing.empty() ? "" : ", ") + "x and y (or lon and lat) columns";
  if (!has(kWeight) && !has(kPower)) missing += std::string(missing.empty() ? "" : ", ") + "a weight or tx_power_dbm column";
  if (!missing.empty()) {
    throw InputError(file, line, "header", "needs " + missing + " (for example: id,lon,lat,tx_power_dbm)");
  }
  return at;
}

SensorDraft read_row(const std::vector<std::string>& fields, const ColumnIndex& at, int line, CsvDelimiter delimiter) {
  SensorDraft d;
  d.line = line;
  d.sensor.origin = "line " + std::to_string(line);
  // The field of column c: nullptr when the file has no such column, or the row is too short.
  const auto field = [&](Column c) -> const std::string* {
    return at[c] != kAbsent && at[c] < fields.size() ? &fields[at[c]] : nullptr;
  };
  const auto required = [&](Column c) -> const std::string* {
    const std::string* f = field(c);
    if (!f) d.problems.push_back("missing " + std::string(kNames[c]) + " (the row has " + std::to_string(fields.size()) + " fields)");
    else if (f->empty()) d.problems.push_back(std::string(kNames[c]) + " is empty");
    return f && !f->empty() ? f : nullptr;
  };
  // Optional fields: an empty one is "not given".
  const auto number = [&](Column c, bool is_required) -> std::optional<double> {
    const std::string* f = is_required ? required(c) : field(c);
    if (!f || f->empty()) return std::nullopt;
    std::string error;
    auto value = to_number(number_text(*f, delimiter), kNames[c], error);
    if (!value) d.problems.push_back(error);
    return value;
  };

  if (const std::string* id = required(kId)) {
    if (valid_utf8(*id)) d.sensor.id = *id;
    else d.problems.push_back("id is not valid UTF-8");
  }
  if (const std::string* name = field(kName)) {  // optional; empty is "not given"
    if (valid_utf8(*name)) d.sensor.name = *name;
    else d.problems.push_back("name is not valid UTF-8");
  }
  if (at[kX] != kAbsent) {
    const auto x = number(kX, true), y = number(kY, true);
    if (x && y) d.xy = Point{*x, *y};
  }
  if (at[kLon] != kAbsent) {
    const auto lon = number(kLon, true), lat = number(kLat, true);
    if (lon && lat) d.lon_lat = LonLat{*lon, *lat};
  }
  d.sensor.weight = number(kWeight, false);
  d.sensor.tx_power_dbm = number(kPower, false);
  d.sensor.position_sigma_m = number(kPositionSigma, false);
  d.sensor.power_sigma_db = number(kPowerSigma, false);
  return d;
}

}  // namespace

std::vector<SensorDraft> parse_sensors_csv(std::string_view text, const std::string& file) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  std::optional<ColumnIndex> columns;
  std::vector<SensorDraft> drafts;
  CsvDelimiter delimiter = CsvDelimiter::kComma;
  int line_number = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    if (!columns) delimiter = detect_delimiter(line);
    const CsvFields fields = split_csv_line(line, delimiter);
    if (!columns) {
      if (!fields.error.empty()) throw InputError(file, line_number, "header", fields.error);
      columns = read_header(fields.values, file, line_number);
      continue;
    }
    if (!fields.error.empty()) {
      SensorDraft& d = drafts.emplace_back();
      d.line = line_number;
      d.sensor.origin = "line " + std::to_string(line_number);
      d.problems.push_back(fields.error);
      continue;
    }
    drafts.push_back(read_row(fields.values, *columns, line_number, delimiter));
  }
  if (!columns) throw InputError(file, 0, "", "no header line (expected a line like: id,lon,lat,tx_power_dbm)");
  return drafts;
}

}  // namespace covmap::io::detail
