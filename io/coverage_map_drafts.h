// The first pass of the coverage-map reader (internal to io/): every feature of the file
// as written, before anything is projected or validated as geometry (io/coverage_map.h has the
// contract of the whole reader).
//
// Two readers fill the same FeatureDrafts:
//   - the reference, read_features_reference: nlohmann's DOM and json_fields.h. It words every
//     problem: a file that is no coverage map at all throws InputError; a feature's problems are
//     kept in its draft, to be reported with everything else the second pass finds.
//   - the fast path, read_features_fast: one pass over the text with JsonScan (io/json_scan.h),
//     filling the drafts directly. It takes only well-formed maps: whenever the text leaves
//     JsonScan's subset, a member is repeated, or the reference would find any problem in the
//     first pass, it returns std::nullopt and the caller runs the reference instead, so every
//     message stays the reference's.
// The contract tested in tests/io/coverage_map_fast_test.cpp: whenever the fast path returns
// drafts, the reference returns the identical drafts (positions bit for bit, labels, crs
// declarations) for the same text and options.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/coverage_map.h"
#include "io/geojson_crs.h"

namespace covmap::io::detail {

using RawRing = std::vector<Point>;       // positions as written, the closing one included
using RawPolygon = std::vector<RawRing>;  // outer ring first

struct FeatureDraft {
  int index = 0;
  std::string label;  // "features[3] (sensor 'a')", or "features[3]" until the sensor is known
  std::string sensor;
  std::string name;    // properties.name, or the sensor id when that is the sensor property
  bool multi = false;  // a MultiPolygon: messages then name the polygon
  std::vector<RawPolygon> polygons;
  std::vector<std::string> problems;
};

inline bool usable(const FeatureDraft& d) { return d.problems.empty(); }

// What the first pass knows about the whole file.
struct FeatureDrafts {
  std::vector<FeatureDraft> drafts;  // file order
  CrsDeclarations crs;               // every "crs" member, in the reference's order
  TopLevelCrs top;                   // the top-level declaration resolved (options.resolve_crs)
};

// The feature property holding a sensor's human name.
inline constexpr const char* kNameProperty = "name";

FeatureDrafts read_features_reference(std::string_view text, const std::string& file, const CoverageMapOptions& options);
std::optional<FeatureDrafts> read_features_fast(std::string_view text, const CoverageMapOptions& options);

// The rest of the reader, the same after either first pass: the limits, the crs judgement, the
// projection and the second pass (io/coverage_map_cells.h); the map, or one InputError with every
// problem. parse_coverage_map is finish_coverage_map(fast drafts, or else the reference's).
// `workers`: threads of the second pass; 0 chooses by the map's size (cell_workers), and any count
// gives the same result (tests and benchmarks set it).
CoverageMap finish_coverage_map(FeatureDrafts first, const std::string& file, const CoverageMapOptions& options,
                                int workers = 0);

// Whether positions are x/y rather than lon/lat: --planar, a CRS the caller gave, covmap's own
// plane declared (kPlaneCrsName), or a top-level declaration (usable or not: a refused one is reported once, not again as every position out of
// lon/lat range). Both readers decide it this one way.
inline bool positions_are_xy(const CoverageMapOptions& options, const TopLevelCrs& top) {
  return options.planar || options.crs_frame || top.frame || top.plane || !top.problems.empty();
}

}  // namespace covmap::io::detail
