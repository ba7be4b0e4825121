#include "tools/mapgen/lonlat_sites_csv.h"

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "io/csv_table.h"
#include "io/input_error.h"

namespace covmap::mapgen {
namespace {

using io::CsvColumn;
using io::InputError;
using io::InputProblem;

enum Column : std::size_t { kId, kLon, kLat, kWeight, kName };
// name is optional: the town's name, kept as written.
constexpr std::array<CsvColumn, 5> kColumns = {{{"id", true, {}},
                                                {"lon", true, {}},
                                                {"lat", true, {}},
                                                {"weight", true, {}},
                                                {"name", false, {}}}};

std::string shown(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

}  // namespace

LonLatSiteTable parse_lonlat_sites_csv(std::string_view text, const std::string& file) {
  io::CsvTable csv(text, file, kColumns, "id,lon,lat,weight");
  LonLatSiteTable table;
  std::vector<InputProblem> problems;
  std::map<std::string, int> id_line;
  std::map<std::pair<double, double>, int> position_line;
  io::CsvRow row;
  while (csv.next(row)) {
    if (!row.error.empty()) {
      problems.push_back({row.line, "", row.error});
      continue;
    }
    LonLatSite site;
    std::vector<std::string> messages;
    std::array<double*, 4> targets = {nullptr, &site.lon, &site.lat, &site.weight};
    for (const Column c : {kId, kLon, kLat, kWeight}) {
      const std::string* value = row.field(c);
      if (!value) {
        messages.push_back(row.missing(c));
      } else if (c == kId) {
        if (value->empty()) messages.push_back("id is empty");
        site.id = *value;
      } else {
        std::string error;
        if (const auto v = row.number(c, error)) *targets[c] = *v;
        else messages.push_back(error);
      }
    }
    if (const std::string* name = row.field(kName)) site.name = *name;
    if (messages.empty()) {
      if (!(std::abs(site.lon) <= 180.0)) messages.push_back("lon must be in [-180, 180] (got " + shown(site.lon) + ")");
      if (!(std::abs(site.lat) < 90.0)) messages.push_back("lat must be in (-90, 90) (got " + shown(site.lat) + ")");
      if (!(std::isfinite(site.weight) && site.weight > 0.0))
        messages.push_back("weight must be finite and positive (got " + shown(site.weight) + ")");
    }
    if (messages.empty() && !site.id.empty()) {
      if (const auto [it, fresh] = id_line.emplace(site.id, row.line); !fresh)
        messages.push_back("id already used on line " + std::to_string(it->second));
      else if (const auto [at, new_position] = position_line.emplace(std::pair{site.lon, site.lat}, row.line); !new_position)
        messages.push_back("same lon/lat as the sensor on line " + std::to_string(at->second));
    }
    const std::string item = site.id.empty() ? std::string() : "sensor '" + site.id + "'";
    for (auto& m : messages) problems.push_back({row.line, item, std::move(m)});
    if (messages.empty()) {
      table.sites.push_back(std::move(site));
      table.line.push_back(row.line);
    }
  }
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
