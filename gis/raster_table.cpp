#include "gis/raster_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>

#include "io/input_error.h"

namespace covmap::gis::detail {
namespace {

std::string trimmed(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t\r\"");
  if (begin == std::string::npos) return {};
  return text.substr(begin, text.find_last_not_of(" \t\r\"") - begin + 1);
}

std::vector<std::string> split(const std::string& line, char delimiter) {
  std::vector<std::string> fields(1);
  for (const char c : line) {
    if (c == delimiter) fields.emplace_back();
    else fields.back() += c;
  }
  for (auto& f : fields) f = trimmed(f);
  return fields;
}

bool parse_integer(const std::string& text, std::int64_t& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && !text.empty();
}

// Adds value -> sensor, or says why not.
void add_entry(RasterSensors& out, const std::string& value_text, const std::string& id, const std::string& name,
               const std::string& where, int line) {
  std::int64_t value = 0;
  if (!parse_integer(value_text, value))
    throw io::InputError(where, line, "value", "\"" + value_text + "\" is not an integer raster value");
  if (id.empty()) throw io::InputError(where, line, "sensor", "empty; every value needs the sensor it stands for");
  if (!out.by_value.emplace(value, RasterSensor{id, name}).second)
    throw io::InputError(where, line, "value", std::to_string(value) + " is listed twice");
}

RasterSensors csv_table(const std::filesystem::path& path) {
  const std::string where = path.string();
  std::ifstream in(path);
  if (!in) throw io::InputError(where, 0, "", "cannot open the raster table");
  std::string header;
  std::getline(in, header);
  const char delimiter = header.find(';') != std::string::npos ? ';' : header.find('\t') != std::string::npos ? '\t' : ',';
  const std::vector<std::string> columns = split(header, delimiter);
  auto column = [&](const std::string& name) {
    const auto it = std::find_if(columns.begin(), columns.end(), [&](const std::string& c) { return ascii_lower(c) == name; });
    return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
  };
  const int value = column("value"), sensor = column("sensor"), name = column("name");
  if (value < 0 || sensor < 0)
    throw io::InputError(where, 1, "", "the header needs columns value and sensor (and may have name); got \"" + header + "\"");
  RasterSensors out;
  out.table = where;
  std::string line;
  for (int number = 2; std::getline(in, line); ++number) {
    if (trimmed(line).empty()) continue;
    const std::vector<std::string> f = split(line, delimiter);
    const auto at = [&](int i) { return i >= 0 && i < static_cast<int>(f.size()) ? f[i] : std::string(); };
    add_entry(out, at(value), at(sensor), at(name), where, number);
  }
  if (out.by_value.empty()) throw io::InputError(where, 0, "", "the raster table lists no values");
  return out;
}

// The band's raster attribute table, if it has one that names sensors.
RasterSensors attribute_table(GDALDatasetH ds, const MapReadOptions& options, const std::string& label) {
  RasterSensors out;
  GDALRasterAttributeTableH rat = GDALGetDefaultRAT(GDALGetRasterBand(ds, options.band));
  if (!rat) return out;
  int value = -1, sensor = -1, name_usage = -1, name = -1;
  for (int i = 0; i < GDALRATGetColumnCount(rat); ++i) {
    const std::string column = ascii_lower(GDALRATGetNameOfCol(rat, i));
    const GDALRATFieldUsage usage = GDALRATGetUsageOfCol(rat, i);
    if (value < 0 && (usage == GFU_MinMax || usage == GFU_Min || column == "value")) value = i;
    if (column == ascii_lower(options.map.sensor_property)) sensor = i;
    if (usage == GFU_Name && name_usage < 0) name_usage = i;
    if (column == "name") name = i;
  }
  if (sensor < 0) sensor = name_usage;
  if (value < 0 || sensor < 0) return out;
  out.table = label + " (raster attribute table)";
  for (int row = 0; row < GDALRATGetRowCount(rat); ++row) {
    const std::string id = GDALRATGetValueAsString(rat, row, sensor);
    add_entry(out, GDALRATGetValueAsString(rat, row, value), id,
              name >= 0 && name != sensor ? GDALRATGetValueAsString(rat, row, name) : "", out.table, row + 1);
  }
  return out;
}

}  // namespace

RasterSensor RasterSensors::of(std::int64_t value) const {
  if (by_value.empty()) return {std::to_string(value), ""};
  const auto it = by_value.find(value);
  return it == by_value.end() ? RasterSensor{} : it->second;
}

RasterSensors raster_sensors(GDALDatasetH ds, const MapReadOptions& options, const std::string& label) {
  if (!options.raster_table.empty()) return csv_table(options.raster_table);
  return attribute_table(ds, options, label);
}

void check_every_value_named(const std::vector<PixelRegions>& regions, const RasterSensors& sensors,
                             const std::string& label) {
  if (sensors.by_value.empty()) return;
  std::vector<std::int64_t> missing;
  for (const PixelRegions& r : regions)
    if (!sensors.by_value.count(r.value)) missing.push_back(r.value);
  if (missing.empty()) return;
  std::string list;
  for (std::size_t i = 0; i < missing.size() && i < 10; ++i) list += (i ? ", " : "") + std::to_string(missing[i]);
  if (missing.size() > 10) list += " and " + std::to_string(missing.size() - 10) + " more";
  throw io::InputError(label, 0, "",
                       std::to_string(missing.size()) + " raster value(s) have no sensor in " + sensors.table + ": " + list +
                           "; add them to the table, or set them to nodata if no sensor serves there");
}

}  // namespace covmap::gis::detail
