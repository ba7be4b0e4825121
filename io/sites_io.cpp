#include "io/sites_io.h"

#include <cctype>
#include <cmath>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "io/fast_readers.h"
#include "io/input_error.h"
#include "io/input_limits.h"
#include "io/json_fields.h"
#include "io/json_out.h"
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
  std::optional<SiteTable> fast;
  if (format == SitesFormat::kJson) fast = detail::parse_sites_json_fast(text);  // io/fast_readers.h
  SiteTable table = fast                            ? std::move(*fast)
                    : format == SitesFormat::kJson ? detail::parse_sites_json(text, file)
                                                   : detail::parse_sites_csv(text, file);
  if (table.sites.size() > kMaxSites)
    throw InputError(file, 0, "", std::to_string(table.sites.size()) + " sites; covmap takes at most " +
                                      std::to_string(kMaxSites) + " (docs/RELIABILITY.md)");
  return table;
}

SiteTable read_sites(const std::filesystem::path& path, SitesFormat format) {
  return parse_sites(detail::read_text_file(path), path.string(), format);
}

void write_sites_json(const std::vector<Site>& sites, std::ostream& stream) {
  // JSON cannot hold NaN or infinity; refuse before the first byte rather than write a file that
  // read_sites rejects.
  for (const auto& s : sites) {
    for (const double v : {s.x, s.y, s.weight}) {
      if (!std::isfinite(v)) throw std::invalid_argument("write_sites_json: site '" + s.id + "' has a non-finite value");
    }
    for (const std::string* text : {&s.id, &s.name}) {
      if (!detail::valid_json_text(*text)) throw std::invalid_argument("write_sites_json: site '" + s.id + "' has text that is not UTF-8");
    }
  }
  // One site per line: readable, diffable, and still valid JSON; numbers as in core/round_trip_numbers.h.
  detail::JsonOut out(stream);
  out.raw("{\"format\":\"covmap.sites/1\",\"sites\":[");
  for (std::size_t i = 0; i < sites.size(); ++i) {
    out.raw(i == 0 ? std::string_view("\n  ") : std::string_view(",\n  "));
    detail::write_site_json(out, sites[i]);
  }
  out.raw(sites.empty() ? "]}\n" : "\n]}\n");
  out.flush();
}

namespace detail {

void write_site_json(JsonOut& out, const Site& s) {
  out.raw("{\"id\":");
  out.string(s.id);
  out.raw(",\"x\":");
  out.number(s.x);
  out.raw(",\"y\":");
  out.number(s.y);
  out.raw(",\"weight\":");
  out.number(s.weight);
  if (!s.name.empty()) {
    out.raw(",\"name\":");
    out.string(s.name);
  }
  out.raw("}");
}

}  // namespace detail
}  // namespace covmap::io
