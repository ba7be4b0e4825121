// The fast path of the covmap.sites/1 reader and of the "sites" array of arc graphs
// (io/fast_readers.h).
#include "io/fast_readers.h"

#include <algorithm>

#include "core/large_buffer.h"
#include "io/input_limits.h"
#include "io/json_fields.h"

namespace covmap::io::detail {
namespace {

enum SiteMember : unsigned { kId = 1, kX = 2, kY = 4, kWeight = 8, kName = 16 };
constexpr unsigned kRequiredSiteMembers = kId | kX | kY | kWeight;

Site scan_site(JsonScan& scan) {
  Site site;
  unsigned seen = 0;
  scan.open('{');
  for (bool first = true; scan.next('}', first);) {
    const std::string_view key = scan.key();
    if (key == "id") {
      first_time(seen, kId);
      site.id = scan.peek() == '"' ? scan.string() : std::string(scan.integer_text());
      if (site.id.empty()) throw FastPathMiss{};
    } else if (key == "x") {
      first_time(seen, kX);
      site.x = scan.number();
    } else if (key == "y") {
      first_time(seen, kY);
      site.y = scan.number();
    } else if (key == "weight") {
      first_time(seen, kWeight);
      site.weight = scan.number();
    } else if (key == "name") {
      first_time(seen, kName);
      if (scan.peek() != '"') throw FastPathMiss{};
      site.name = scan.string();
    } else {
      scan.skip_value();
    }
  }
  if ((seen & kRequiredSiteMembers) != kRequiredSiteMembers || !site_values_valid(site)) throw FastPathMiss{};
  return site;
}

}  // namespace

SiteTable scan_sites(JsonScan& scan) {
  // Straight into the table, with no SiteDraft in between: on large inputs the drafts would be
  // many MB of fresh pages written once and copied out again. Room for as many sites as the rest of
  // the text could hold, so that a million sites are not moved again and again as the vectors grow;
  // the pages of unused room are never touched.
  constexpr std::size_t kShortestSiteBytes = 30;  // {"id":1,"x":0,"y":0,"weight":1},
  const std::size_t room = std::min(scan.remaining() / kShortestSiteBytes, kMaxSites + 1);
  SiteTable table;
  table.sites.reserve(room);
  table.origin.reserve(room);
  // The touched part in huge pages where the system has them (a fault per fresh 4 KiB page cost a
  // fifth of reading 10^5 sites; core/large_buffer.h).
  advise_huge_pages(table.sites.data(), table.sites.capacity() * sizeof(Site));
  advise_huge_pages(table.origin.data(), table.origin.capacity() * sizeof(std::string));
  scan.open('[');
  for (bool first = true; scan.next(']', first);) {
    table.origin.push_back(element_path("sites", table.sites.size()));
    table.sites.push_back(scan_site(scan));
  }
  return table;
}

void check_sites_or_miss(const SiteTable& table) {
  const std::vector<Site>& sites = table.sites;
  if (sites.empty()) throw FastPathMiss{};
  const SiteAt site = [&sites](std::size_t i) { return &sites[i]; };
  const Repeat miss = [](std::size_t, std::size_t) { throw FastPathMiss{}; };
  find_repeated_positions(sites.size(), site, miss);
  find_repeated_ids(sites.size(), site, miss);
}

std::optional<SiteTable> parse_sites_json_fast(std::string_view text) {
  enum : unsigned { kFormat = 1, kSites = 2 };
  try {
    JsonScan scan(text);
    std::optional<SiteTable> table;
    unsigned seen = 0;
    scan.open('{');
    for (bool first = true; scan.next('}', first);) {
      const std::string_view key = scan.key();
      if (key == "format") {
        first_time(seen, kFormat);
        expect_string(scan, "covmap.sites/1");
      } else if (key == "sites") {
        first_time(seen, kSites);
        table = scan_sites(scan);
        check_sites_or_miss(*table);
      } else {
        scan.skip_value();
      }
    }
    scan.expect_end();
    if (!(seen & kFormat) || !table) return std::nullopt;
    return table;
  } catch (const FastPathMiss&) {
    return std::nullopt;
  }
}

}  // namespace covmap::io::detail
