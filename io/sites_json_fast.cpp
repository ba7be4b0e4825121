// The fast path of the covmap.sites/1 reader and of the "sites" array of arc graphs
// (io/fast_readers.h).
#include "io/fast_readers.h"

#include <algorithm>

#include "core/large_buffer.h"
#include "io/input_error.h"
#include "io/input_limits.h"
#include "io/json_fields.h"

namespace covmap::io::detail {
namespace {

enum SiteMember : unsigned { kId = 1, kX = 2, kY = 4, kWeight = 8, kName = 16 };
constexpr unsigned kRequiredSiteMembers = kId | kX | kY | kWeight;

SiteDraft scan_site(JsonScan& scan, std::size_t i) {
  SiteDraft draft;
  unsigned seen = 0;
  scan.open('{');
  for (bool first = true; scan.next('}', first);) {
    const std::string_view key = scan.key();
    if (key == "id") {
      first_time(seen, kId);
      draft.site.id = scan.peek() == '"' ? scan.string() : std::string(scan.integer_text());
      if (draft.site.id.empty()) throw FastPathMiss{};
    } else if (key == "x") {
      first_time(seen, kX);
      draft.site.x = scan.number();
    } else if (key == "y") {
      first_time(seen, kY);
      draft.site.y = scan.number();
    } else if (key == "weight") {
      first_time(seen, kWeight);
      draft.site.weight = scan.number();
    } else if (key == "name") {
      first_time(seen, kName);
      if (scan.peek() != '"') throw FastPathMiss{};
      draft.site.name = scan.string();
    } else {
      scan.skip_value();
    }
  }
  if ((seen & kRequiredSiteMembers) != kRequiredSiteMembers) throw FastPathMiss{};
  draft.origin = element_path("sites", i);
  check_site_values(draft);
  if (!draft.usable()) throw FastPathMiss{};
  return draft;
}

}  // namespace

std::vector<SiteDraft> scan_site_drafts(JsonScan& scan) {
  // Room for as many sites as the rest of the text could hold, so that a million drafts are not
  // moved again and again as the vector grows; the pages of unused room are never touched.
  constexpr std::size_t kShortestSiteBytes = 30;  // {"id":1,"x":0,"y":0,"weight":1},
  std::vector<SiteDraft> drafts;
  drafts.reserve(std::min(scan.remaining() / kShortestSiteBytes, kMaxSites + 1));
  // The touched part in huge pages where the system has them (a fault per fresh 4 KiB page cost a
  // fifth of reading 10^5 sites; core/large_buffer.h).
  advise_huge_pages(drafts.data(), drafts.capacity() * sizeof(SiteDraft));
  scan.open('[');
  for (bool first = true; scan.next(']', first);) drafts.push_back(scan_site(scan, drafts.size()));
  return drafts;
}

SiteTable finish_sites_or_miss(std::vector<SiteDraft> drafts) {
  try {
    return finish_sites(std::move(drafts), "");
  } catch (const InputError&) {
    throw FastPathMiss{};
  }
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
        table = finish_sites_or_miss(scan_site_drafts(scan));
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
