#include "io/sites_io.h"

#include <cctype>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "io/input_error.h"
#include "io/input_limits.h"
#include "io/json_fields.h"
#include "io/site_parsers.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

SitesFormat detect(const std::filesystem::path& path, std::string_view text) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".json") return SitesFormat::kJson;
  if (ext == ".csv") return SitesFormat::kCsv;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  // A CSV header starts with a column name, never with a brace.
  const std::string_view body = detail::trim(text);
  return !body.empty() && body.front() == '{' ? SitesFormat::kJson : SitesFormat::kCsv;
}

}  // namespace

SiteTable parse_sites(std::string_view text, const std::string& file, SitesFormat format) {
  if (format == SitesFormat::kDetect) format = detect(file, text);
  SiteTable table = format == SitesFormat::kJson ? detail::parse_sites_json(text, file) : detail::parse_sites_csv(text, file);
  if (table.sites.size() > kMaxSites)
    throw InputError(file, 0, "", std::to_string(table.sites.size()) + " sites; covmap takes at most " +
                                      std::to_string(kMaxSites) + " (docs/RELIABILITY.md)");
  return table;
}

SiteTable read_sites(const std::filesystem::path& path, SitesFormat format) {
  return parse_sites(detail::read_text_file(path), path.string(), format);
}

void write_sites_json(const std::vector<Site>& sites, std::ostream& out) {
  // One site per line: readable, diffable, and still valid JSON. nlohmann writes doubles in the
  // shortest form that reads back to the same bits.
  out << "{\"format\":\"covmap.sites/1\",\"sites\":[";
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const auto& s = sites[i];
    for (const double v : {s.x, s.y, s.weight}) {
      // JSON cannot hold NaN or infinity (nlohmann would write null); refuse rather than write a
      // file that read_sites rejects.
      if (!std::isfinite(v)) throw std::invalid_argument("write_sites_json: site '" + s.id + "' has a non-finite value");
    }
    nlohmann::ordered_json site = {{"id", s.id}, {"x", s.x}, {"y", s.y}, {"weight", s.weight}};
    if (!s.name.empty()) site["name"] = s.name;
    out << (i == 0 ? "\n  " : ",\n  ") << site.dump();
  }
  out << (sites.empty() ? "]}\n" : "\n]}\n");
}

}  // namespace covmap::io
