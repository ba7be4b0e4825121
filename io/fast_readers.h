// The fast paths of the covmap.sites/1 and covmap.arcgraph/1 readers, and the reference readers
// they fall back on (internal to io/).
//
// parse_sites and parse_diagram_json first try the fast path: one pass over the text with
// JsonScan, filling the result directly, holding every rule the reference reader holds. It
// returns nothing (std::nullopt) as soon as anything is out of the ordinary: a JSON construct
// outside JsonScan's subset, a member out of the order it needs (arcs before nodes, sites after
// arcs when they label them, faces before arcs), a duplicated member, any failed check. The
// reference reader (nlohmann's DOM and json_fields.h) then reads the text again, and is the only
// one that reports errors, so every message is the reference's. The contract tested in
// tests/io/fast_readers_test.cpp: whenever the fast path returns a result, the reference returns
// the identical result (bit for bit) for the same text.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagram.h"
#include "io/diagram_json.h"
#include "io/geojson_crs.h"
#include "io/json_scan.h"
#include "io/site_validation.h"
#include "io/sites_io.h"

namespace covmap::io::detail {

std::optional<SiteTable> parse_sites_json_fast(std::string_view text);
std::optional<Diagram> parse_diagram_json_fast(std::string_view text, ArcLabels labels);

// The reference arc graph reader (the sites one is parse_sites_json in site_parsers.h).
Diagram parse_diagram_json_reference(std::string_view text, const std::string& file, ArcLabels labels);

// The elements of a "sites" array, each checked as one site (site_values_valid), with their
// origins ("sites[3]"); misses on any problem. Empty when the array is.
SiteTable scan_sites(JsonScan& scan);
// finish_sites's whole-list checks (at least one site, unique ids, unique positions), missing
// instead of throwing.
void check_sites_or_miss(const SiteTable& table);

// Reads the object that comes next: member(key) for each member, which must read the value.
template <class Member>
void scan_object(JsonScan& scan, Member&& member) {
  scan.open('{');
  for (bool first = true; scan.next('}', first);) member(scan.key());
}

// Misses unless the next value is the string `expected` (a format tag, a GeoJSON type).
inline void expect_string(JsonScan& scan, std::string_view expected) {
  if (scan.peek() != '"' || scan.string() != expected) throw FastPathMiss{};
}

// A whole text holding a GeoJSON FeatureCollection: feature(i) reads element i of "features".
// Returns the text of the collection's "crs" member (empty without one). Misses without "type"
// "FeatureCollection" or without features, on a repeated member, and on a "format" member (a
// covmap.sites/1 file, when the kind of file is detected from its content).
template <class Feature>
std::string_view scan_feature_collection(JsonScan& scan, Feature&& feature) {
  enum : unsigned { kType = 1, kFeatures = 2, kCrs = 4 };
  unsigned seen = 0;
  std::size_t count = 0;
  std::string_view crs;
  scan_object(scan, [&](std::string_view key) {
    if (key == "type") {
      first_time(seen, kType);
      expect_string(scan, "FeatureCollection");
    } else if (key == "features") {
      first_time(seen, kFeatures);
      scan.open('[');
      for (bool first = true; scan.next(']', first);) feature(count++);
    } else if (key == "crs") {
      first_time(seen, kCrs);
      crs = scan.raw_value();
    } else if (key == "format") {
      throw FastPathMiss{};
    } else {
      scan.skip_value();
    }
  });
  scan.expect_end();
  if (!(seen & kType) || !(seen & kFeatures) || count == 0) throw FastPathMiss{};
  return crs;
}

// A JSON array of two numbers, [x, y], as a point. With `more_allowed` further elements of any
// kind follow and are skipped (a GeoJSON position's altitude); otherwise they miss.
inline Point scan_number_pair(JsonScan& scan, bool more_allowed) {
  Point p;
  scan.open('[');
  bool first = true;
  if (!scan.next(']', first)) throw FastPathMiss{};
  p.x = scan.number();
  if (!scan.next(']', first)) throw FastPathMiss{};
  p.y = scan.number();
  while (scan.next(']', first)) {
    if (!more_allowed) throw FastPathMiss{};
    scan.skip_value();
  }
  return p;
}

// Records a GeoJSON "crs" member read as text (JsonScan::raw_value) as the reference records it;
// nothing for an empty text (no member). Text JsonScan took and the JSON library refuses misses.
inline void record_crs(CrsDeclarations& crs, std::string_view text, const std::string& path) {
  if (text.empty()) return;
  try {
    crs.add_text(text, path);
  } catch (const Json::exception&) {
    throw FastPathMiss{};
  }
}

// Marks a known member as seen, missing on a repeat: the reference keeps the last of duplicated
// members, which a one-pass reader cannot do.
inline void first_time(unsigned& seen, unsigned bit) {
  if (seen & bit) throw FastPathMiss{};
  seen |= bit;
}

// A member that is a string or null (a name): null leaves `out` as it is; any other value misses.
inline void scan_nullable_string(JsonScan& scan, std::string& out) {
  if (scan.null()) return;
  if (scan.peek() != '"') throw FastPathMiss{};
  out = scan.string();
}

}  // namespace covmap::io::detail
