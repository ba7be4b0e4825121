// The CSV syntax for reported sensors: a header naming the columns, then one sensor per line.
// Lines, delimiters, quoting and numbers as io/csv_table.h reads them; the columns differ.
#include <array>
#include <string>

#include "io/csv_table.h"
#include "io/reported_sensors_parsers.h"
#include "io/text_util.h"

namespace covmap::io::detail {
namespace {

enum Column : std::size_t { kId, kName, kX, kY, kLon, kLat, kWeight, kPower, kPositionSigma, kPowerSigma, kColumnCount };
// All optional to the table; which combinations a file needs is checked by check_header.
constexpr std::array<CsvColumn, kColumnCount> kColumns = {{{"id", false, {}},
                                                           {"name", false, {}},
                                                           {"x", false, {}},
                                                           {"y", false, {}},
                                                           {"lon", false, {}},
                                                           {"lat", false, {}},
                                                           {"weight", false, {}},
                                                           {"tx_power_dbm", false, {}},
                                                           {"position_sigma_m", false, {}},
                                                           {"power_sigma_db", false, {}}}};

void check_header(const CsvTable& table) {
  const auto has = [&](Column c) { return table.has(c); };
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
    throw InputError(table.file(), table.header_line(), "header", "needs " + missing + " (for example: id,lon,lat,tx_power_dbm)");
  }
}

SensorDraft read_row(const CsvTable& table, const CsvRow& row) {
  SensorDraft d;
  d.line = row.line;
  d.sensor.origin = "line " + std::to_string(row.line);
  const auto required = [&](Column c) -> const std::string* {
    const std::string* f = row.field(c);
    if (!f) d.problems.push_back(row.missing(c));
    else if (f->empty()) d.problems.push_back(std::string(kColumns[c].name) + " is empty");
    return f && !f->empty() ? f : nullptr;
  };
  // Optional fields: an empty one is "not given".
  const auto number = [&](Column c, bool is_required) -> std::optional<double> {
    const std::string* f = is_required ? required(c) : row.field(c);
    if (!f || f->empty()) return std::nullopt;
    std::string error;
    auto value = row.number(c, error);
    if (!value) d.problems.push_back(error);
    return value;
  };

  if (const std::string* id = required(kId)) {
    if (valid_utf8(*id)) d.sensor.id = *id;
    else d.problems.push_back("id is not valid UTF-8");
  }
  if (const std::string* name = row.field(kName)) {  // optional; empty is "not given"
    if (valid_utf8(*name)) d.sensor.name = *name;
    else d.problems.push_back("name is not valid UTF-8");
  }
  if (table.has(kX)) {
    const auto x = number(kX, true), y = number(kY, true);
    if (x && y) d.xy = Point{*x, *y};
  }
  if (table.has(kLon)) {
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
  CsvTable table(text, file, kColumns, "id,lon,lat,tx_power_dbm");
  check_header(table);
  std::vector<SensorDraft> drafts;
  CsvRow row;
  while (table.next(row)) {
    if (!row.error.empty()) {
      SensorDraft& d = drafts.emplace_back();
      d.line = row.line;
      d.sensor.origin = "line " + std::to_string(row.line);
      d.problems.push_back(row.error);
      continue;
    }
    drafts.push_back(read_row(table, row));
  }
  return drafts;
}

}  // namespace covmap::io::detail
