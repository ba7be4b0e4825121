// covmap::io sites files: read a list of weighted sites (JSON or CSV), write it back as JSON.
//
// Accepted input (docs/FORMATS.md has the full grammar):
//   JSON  {"format":"covmap.sites/1","sites":[{"id":"a","x":0,"y":0,"weight":1}, ...]}
//         id is a non-empty string or an integer; x, y, weight are numbers; all four required.
//         An optional "name" (a string; anything else is rejected) is kept in Site::name.
//   CSV   a header naming the columns id, x, y, weight in any order, optionally name (extra
//         columns are ignored), then one site per row; an empty name field means no name. Fields are trimmed; blank lines and lines starting with # are
//         skipped; a field may be double-quoted ("a,b", "" for a quote).
// The format is chosen by extension (.json / .csv), otherwise by content (a leading '{' is JSON).
//
// Guaranteed on success: at least one site; every coordinate finite; every weight finite and > 0;
// ids unique; no two sites at exactly the same position (a duplicate position has no meaningful
// bisector). Sites keep file order.
//
// Rejected with InputError: unreadable file, invalid JSON (with byte offset and line), a missing or
// wrong format tag or header, and per-site problems (missing field, non-numeric, non-finite,
// non-positive weight, duplicate id, duplicate position). Per-site problems are all collected and
// reported together, each naming the line (CSV) or index (JSON) and the site id.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagram.h"

namespace covmap::io {

struct SiteTable {
  std::vector<Site> sites;
  // Per site, where it was read from, for messages in later stages: "line 7" or "sites[3]".
  std::vector<std::string> origin;
};

enum class SitesFormat { kDetect, kJson, kCsv };

SiteTable read_sites(const std::filesystem::path& path, SitesFormat format = SitesFormat::kDetect);

// Parses text already in memory; `file` is only used in error messages.
SiteTable parse_sites(std::string_view text, const std::string& file, SitesFormat format = SitesFormat::kDetect);

// Writes covmap.sites/1, one site per line; doubles are written so they read back bit-exactly;
// "name" only for sites that have one.
void write_sites_json(const std::vector<Site>& sites, std::ostream& out);

}  // namespace covmap::io
