// The fast first pass of the coverage-map reader (io/coverage_map_drafts.h): the drafts the
// reference reader (coverage_map_features.cpp) would make, read in one pass with JsonScan. Every
// rule the reference applies in its first pass is held here as a condition of taking the text;
// whatever breaks one is a miss, and the reference reads the file again and words the problem.
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "io/coverage_map_drafts.h"
#include "io/fast_readers.h"
#include "io/input_limits.h"
#include "io/json_fields.h"
#include "io/text_util.h"

namespace covmap::io::detail {
namespace {

// Array nesting of a geometry's coordinates, counted on a copy of the scanner so nothing is
// consumed: 3 for a Polygon (rings of positions of numbers), 4 for a MultiPolygon. Reading by
// depth lets "coordinates" come before "type", as in files written with sorted member names.
constexpr int kPolygonDepth = 3;
constexpr int kMultiPolygonDepth = 4;

int array_depth(JsonScan probe) {
  int depth = 0;
  while (probe.peek() == '[') {
    probe.open('[');
    ++depth;
  }
  return depth;
}

// A ring, which RFC 7946 requires to end where it starts (compared as the reference does). The
// positions gather in `scratch`, reused from ring to ring, and the ring is one allocation of its
// exact size: growing each ring's own vector costs a chain of reallocations and fresh memory that
// is touched and given back (a page fault per 4 KiB on this kind of machine, docs/PERFORMANCE.md).
RawRing scan_ring(JsonScan& scan, RawRing& scratch) {
  RawRing& ring = scratch;
  ring.clear();
  scan.open('[');
  // [x, y] or [lon, lat]; further values (altitude) are skipped, as the reference ignores them.
  for (bool first = true; scan.next(']', first);) ring.push_back(scan_number_pair(scan, true));
  if (ring.empty() || ring.front().x != ring.back().x || ring.front().y != ring.back().y) throw FastPathMiss{};
  return RawRing(ring.begin(), ring.end());
}

RawPolygon scan_polygon(JsonScan& scan, RawRing& scratch) {
  RawPolygon polygon;
  scan.open('[');
  for (bool first = true; scan.next(']', first);) polygon.push_back(scan_ring(scan, scratch));
  if (polygon.empty()) throw FastPathMiss{};
  return polygon;
}

// A "crs" member's text, kept for the reference JSON library to read after the scan (rare, small).
struct PendingCrs {
  std::string path;  // the member's owner, as the reference names it
  std::string_view text;
};

// Geometry (a Polygon or MultiPolygon with at least one polygon) into draft.polygons; its "crs"
// text, if any, into `crs`.
void scan_geometry(JsonScan& scan, FeatureDraft& draft, std::string_view& crs, RawRing& scratch) {
  enum : unsigned { kType = 1, kCoordinates = 2, kCrs = 4 };
  unsigned seen = 0;
  std::string type;
  int depth = 0;
  scan_object(scan, [&](std::string_view key) {
    if (key == "type") {
      first_time(seen, kType);
      if (scan.peek() != '"') throw FastPathMiss{};
      type = scan.string();
    } else if (key == "coordinates") {
      first_time(seen, kCoordinates);
      depth = array_depth(scan);
      if (depth == kPolygonDepth) {
        draft.polygons.push_back(scan_polygon(scan, scratch));
      } else if (depth == kMultiPolygonDepth) {
        scan.open('[');
        for (bool first_polygon = true; scan.next(']', first_polygon);) draft.polygons.push_back(scan_polygon(scan, scratch));
      } else {
        throw FastPathMiss{};
      }
    } else if (key == "crs") {
      first_time(seen, kCrs);
      crs = scan.raw_value();
    } else {
      scan.skip_value();
    }
  });
  if (!(seen & kType) || !(seen & kCoordinates)) throw FastPathMiss{};
  if (type != (depth == kPolygonDepth ? "Polygon" : "MultiPolygon")) throw FastPathMiss{};
  draft.multi = depth == kMultiPolygonDepth;
}

// The sensor (a non-empty string or an integer, kept as its text) and the optional name.
void scan_properties(JsonScan& scan, const std::string& sensor_property, FeatureDraft& draft) {
  enum : unsigned { kSensor = 1, kName = 2 };
  unsigned seen = 0;
  scan_object(scan, [&](std::string_view key) {
    if (key == sensor_property) {
      first_time(seen, kSensor);
      draft.sensor = scan.peek() == '"' ? scan.string() : std::string(scan.integer_text());
      if (draft.sensor.empty()) throw FastPathMiss{};
    } else if (key == kNameProperty) {
      first_time(seen, kName);
      scan_nullable_string(scan, draft.name);
    } else {
      scan.skip_value();
    }
  });
  if (!(seen & kSensor)) throw FastPathMiss{};
  if (sensor_property == kNameProperty) draft.name = draft.sensor;
}

// One Feature; its "crs" members go to `pending` in the reference's order (the feature's own, then
// its geometry's, whatever their order in the text).
FeatureDraft scan_feature(JsonScan& scan, std::size_t i, const std::string& sensor_property, std::vector<PendingCrs>& pending,
                          RawRing& scratch) {
  enum : unsigned { kType = 1, kProperties = 2, kGeometry = 4, kCrs = 8 };
  constexpr unsigned kRequired = kType | kProperties | kGeometry;
  FeatureDraft draft;
  draft.index = static_cast<int>(i);
  std::string_view feature_crs, geometry_crs;
  unsigned seen = 0;
  scan_object(scan, [&](std::string_view key) {
    if (key == "type") {
      first_time(seen, kType);
      expect_string(scan, "Feature");
    } else if (key == "properties") {
      first_time(seen, kProperties);
      scan_properties(scan, sensor_property, draft);
    } else if (key == "geometry") {
      first_time(seen, kGeometry);
      scan_geometry(scan, draft, geometry_crs, scratch);
    } else if (key == "crs") {
      first_time(seen, kCrs);
      feature_crs = scan.raw_value();
    } else {
      scan.skip_value();
    }
  });
  if ((seen & kRequired) != kRequired) throw FastPathMiss{};
  // The reference names the feature's crs before it knows the sensor, the geometry's after.
  draft.label = element_path("features", i);
  if (!feature_crs.empty()) pending.push_back({draft.label, feature_crs});
  draft.label += " (sensor " + quote_id(draft.sensor) + ")";
  if (!geometry_crs.empty()) pending.push_back({member_path(draft.label, "geometry"), geometry_crs});
  return draft;
}

// The reference's range checks of positions as read: any position it would report is a miss.
bool positions_in_range(const std::vector<FeatureDraft>& drafts, bool xy) {
  for (const FeatureDraft& d : drafts)
    for (const RawPolygon& polygon : d.polygons)
      for (const RawRing& ring : polygon)
        for (const Point& p : ring) {
          if (xy ? std::abs(p.x) > kMaxPlanarCoordinate || std::abs(p.y) > kMaxPlanarCoordinate
                 : std::abs(p.x) > 180.0 || std::abs(p.y) > 90.0)
            return false;
        }
  return true;
}

}  // namespace

std::optional<FeatureDrafts> read_features_fast(std::string_view text, const CoverageMapOptions& options) {
  try {
    JsonScan scan(text);
    FeatureDrafts out;
    std::vector<PendingCrs> pending;
    RawRing scratch;
    const std::string_view top_crs = scan_feature_collection(scan, [&](std::size_t i) {
      if (i == kMaxMapFeatures) throw FastPathMiss{};
      out.drafts.push_back(scan_feature(scan, i, options.sensor_property, pending, scratch));
    });
    // The reference's order: the top-level declaration, resolved before the features' are added.
    record_crs(out.crs, top_crs, "");
    if (!options.crs_frame) out.top = resolve_top_level(out.crs, options.resolve_crs, options.planar);
    for (const PendingCrs& p : pending) record_crs(out.crs, p.text, p.path);
    if (!positions_in_range(out.drafts, positions_are_xy(options, out.top))) return std::nullopt;
    return out;
  } catch (const FastPathMiss&) {
    return std::nullopt;
  }
}

}  // namespace covmap::io::detail
