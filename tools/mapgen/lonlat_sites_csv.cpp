#include "tools/mapgen/lonlat_sites_csv.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "io/input_error.h"

namespace covmap::mapgen {
namespace {

using io::InputError;
using io::InputProblem;

constexpr std::array<std::string_view, 4> kColumns = {"id", "lon", "lat", "weight"};
constexpr std::string_view kNameColumn = "name";  // optional: the town's name, kept as written
constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);

std::string_view trim(std::string_view text) {
  const auto not_space = [](char c) { return c != ' ' && c != '\t' && c != '\r'; };
  while (!text.empty() && !not_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && !not_space(text.back())) text.remove_suffix(1);
  return text;
}

std::vector<std::string> split(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.emplace_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

std::string lower(std::string_view text) {
  std::string out(text);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::optional<double> number(const std::string& field, std::string_view name, std::string& error) {
  std::string_view digits = field;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (field.empty() || ec != std::errc() || end != digits.data() + digits.size()) {
    error = std::string(name) + " is not a number (got '" + field + "')";
    return std::nullopt;
  }
  return value;
}

std::string shown(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

}  // namespace

LonLatSiteTable parse_lonlat_sites_csv(std::string_view text, const std::string& file) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  std::optional<std::array<std::size_t, 4>> column;
  std::size_t name_column = kAbsent;
  LonLatSiteTable table;
  std::vector<InputProblem> problems;
  std::map<std::string, int> id_line;
  std::map<std::pair<double, double>, int> position_line;
  int line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string> fields = split(line);
    if (!column) {
      std::array<std::size_t, 4> found{};
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        const auto count = std::count_if(fields.begin(), fields.end(), [&](const std::string& f) { return lower(f) == kColumns[c]; });
        if (count != 1)
          throw InputError(file, line_number, "header",
                           std::string(count == 0 ? "missing" : "repeated") + " column '" + std::string(kColumns[c]) +
                               "' (the header must name id, lon, lat and weight once each, in any order)");
        found[c] = static_cast<std::size_t>(
            std::find_if(fields.begin(), fields.end(), [&](const std::string& f) { return lower(f) == kColumns[c]; }) -
            fields.begin());
      }
      column = found;
      const auto is_name = [](const std::string& f) { return lower(f) == kNameColumn; };
      if (std::count_if(fields.begin(), fields.end(), is_name) > 1)
        throw InputError(file, line_number, "header", "repeated column 'name'");
      if (const auto it = std::find_if(fields.begin(), fields.end(), is_name); it != fields.end())
        name_column = static_cast<std::size_t>(it - fields.begin());
      continue;
    }
    if (line.find('"') != std::string_view::npos) {
      problems.push_back({line_number, "", "quoted fields are not supported"});
      continue;
    }
    LonLatSite site;
    std::vector<std::string> messages;
    const auto field = [&](std::size_t c) -> const std::string* {
      return (*column)[c] < fields.size() ? &fields[(*column)[c]] : nullptr;
    };
    std::array<double*, 4> targets = {nullptr, &site.lon, &site.lat, &site.weight};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      const std::string* value = field(c);
      if (!value) {
        messages.push_back("missing " + std::string(kColumns[c]) + " (the row has " + std::to_string(fields.size()) + " fields)");
      } else if (c == 0) {
        if (value->empty()) messages.push_back("id is empty");
        site.id = *value;
      } else {
        std::string error;
        if (const auto v = number(*value, kColumns[c], error)) *targets[c] = *v;
        else messages.push_back(error);
      }
    }
    if (name_column < fields.size()) site.name = fields[name_column];
    if (messages.empty()) {
      if (!(std::abs(site.lon) <= 180.0)) messages.push_back("lon must be in [-180, 180] (got " + shown(site.lon) + ")");
      if (!(std::abs(site.lat) < 90.0)) messages.push_back("lat must be in (-90, 90) (got " + shown(site.lat) + ")");
      if (!(std::isfinite(site.weight) && site.weight > 0.0))
        messages.push_back("weight must be finite and positive (got " + shown(site.weight) + ")");
    }
    if (messages.empty() && !site.id.empty()) {
      if (const auto [it, fresh] = id_line.emplace(site.id, line_number); !fresh)
        messages.push_back("id already used on line " + std::to_string(it->second));
      else if (const auto [at, new_position] = position_line.emplace(std::pair{site.lon, site.lat}, line_number); !new_position)
        messages.push_back("same lon/lat as the sensor on line " + std::to_string(at->second));
    }
    const std::string item = site.id.empty() ? std::string() : "sensor '" + site.id + "'";
    for (auto& m : messages) problems.push_back({line_number, item, std::move(m)});
    if (messages.empty()) {
      table.sites.push_back(std::move(site));
      table.line.push_back(line_number);
    }
  }
  if (!column) throw InputError(file, 0, "", "no header line (expected a line like: id,lon,lat,weight)");
  if (!problems.empty()) throw InputError(file, std::move(problems));
  if (table.sites.empty()) throw InputError(file, 0, "", "no sensors after the header");
  return table;
}

LonLatSiteTable read_lonlat_sites_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), 0, "", "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path.string(), 0, "", "cannot read the file");
  return parse_lonlat_sites_csv(text.str(), path.string());
}

}  // namespace covmap::mapgen
