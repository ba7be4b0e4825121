// The fast path of the reported sensors' GeoJSON (io/reported_sensors_parsers.h): the drafts
// parse_sensors_geojson would make, read in one pass with JsonScan (io/fast_readers.h). Every rule
// of the reference's is a condition of taking the text; anything the reference would report, or
// that JsonScan does not take, is a miss, and the reference reads the file again.
#include <algorithm>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/fast_readers.h"
#include "io/json_fields.h"
#include "io/reported_sensors_parsers.h"

namespace covmap::io::detail {
namespace {

// An id candidate: nullopt for null; the text of a string or of an integer token. Anything else
// misses (the reference would report it if it is the candidate used, and ignore it otherwise: a
// miss is right either way).
std::optional<std::string> scan_id(JsonScan& scan) {
  if (scan.null()) return std::nullopt;
  if (scan.peek() == '"') return scan.string();
  return std::string(scan.integer_text());
}

// An optional number: absent or null is not given.
std::optional<double> scan_optional_number(JsonScan& scan) {
  if (scan.null()) return std::nullopt;
  return scan.number();
}

// What one feature holds, before the file's CRS says whether its position is x/y or lon/lat.
struct FeatureScan {
  SensorDraft draft;
  Point position;
  // The id candidates in the reference's order: properties.id, properties.sensor, the feature's "id".
  std::optional<std::string> ids[3];
  std::string_view feature_crs, geometry_crs;
};

void scan_point(JsonScan& scan, FeatureScan& f) {
  enum : unsigned { kType = 1, kCoordinates = 2, kCrs = 4 };
  unsigned seen = 0;
  scan_object(scan, [&](std::string_view key) {
    if (key == "type") first_time(seen, kType), expect_string(scan, "Point");
    else if (key == "coordinates") first_time(seen, kCoordinates), f.position = scan_number_pair(scan, true);
    else if (key == "crs") first_time(seen, kCrs), f.geometry_crs = scan.raw_value();
    else scan.skip_value();
  });
  if (!(seen & kType) || !(seen & kCoordinates)) throw FastPathMiss{};
}

void scan_properties(JsonScan& scan, FeatureScan& f) {
  enum : unsigned { kId = 1, kSensor = 2, kName = 4, kWeight = 8, kPower = 16, kPositionSigma = 32, kPowerSigma = 64 };
  if (scan.null()) return;  // null properties: none
  ReportedSensor& s = f.draft.sensor;
  unsigned seen = 0;
  scan_object(scan, [&](std::string_view key) {
    if (key == "id") first_time(seen, kId), f.ids[0] = scan_id(scan);
    else if (key == "sensor") first_time(seen, kSensor), f.ids[1] = scan_id(scan);
    else if (key == "weight") first_time(seen, kWeight), s.weight = scan_optional_number(scan);
    else if (key == "tx_power_dbm") first_time(seen, kPower), s.tx_power_dbm = scan_optional_number(scan);
    else if (key == "position_sigma_m") first_time(seen, kPositionSigma), s.position_sigma_m = scan_optional_number(scan);
    else if (key == "power_sigma_db") first_time(seen, kPowerSigma), s.power_sigma_db = scan_optional_number(scan);
    else if (key == "name") {
      first_time(seen, kName);
      scan_nullable_string(scan, s.name);
    } else {
      scan.skip_value();
    }
  });
}

FeatureScan scan_feature(JsonScan& scan, std::size_t i) {
  enum : unsigned { kType = 1, kProperties = 2, kGeometry = 4, kId = 8, kCrs = 16 };
  FeatureScan f;
  f.draft.sensor.origin = element_path("features", i);
  unsigned seen = 0;
  scan_object(scan, [&](std::string_view key) {
    if (key == "type") first_time(seen, kType), expect_string(scan, "Feature");
    else if (key == "properties") first_time(seen, kProperties), scan_properties(scan, f);
    else if (key == "geometry") first_time(seen, kGeometry), scan_point(scan, f);
    else if (key == "id") first_time(seen, kId), f.ids[2] = scan_id(scan);
    else if (key == "crs") first_time(seen, kCrs), f.feature_crs = scan.raw_value();
    else scan.skip_value();
  });
  if (!(seen & kType) || !(seen & kGeometry)) throw FastPathMiss{};
  // The first candidate given decides; an empty id is the reference's to report.
  const auto id = std::find_if(std::begin(f.ids), std::end(f.ids), [](const auto& c) { return c.has_value(); });
  if (id == std::end(f.ids) || id->value().empty()) throw FastPathMiss{};
  f.draft.sensor.id = id->value();
  return f;
}

}  // namespace

std::optional<std::vector<SensorDraft>> parse_sensors_geojson_fast(std::string_view text, bool planar, bool xy_crs,
                                                                   const CrsResolver& resolve,
                                                                   std::shared_ptr<const MapFrame>& declared,
                                                                   std::vector<InputProblem>& file_problems) {
  try {
    JsonScan scan(text);
    std::vector<FeatureScan> features;
    const std::string_view top_crs =
        scan_feature_collection(scan, [&](std::size_t i) { features.push_back(scan_feature(scan, i)); });
    // The reference's order: the top-level declaration, resolved, then each feature's and its
    // geometry's.
    CrsDeclarations crs;
    record_crs(crs, top_crs, "");
    TopLevelCrs top = xy_crs ? TopLevelCrs{} : resolve_top_level(crs, resolve, planar);
    const bool xy = planar || xy_crs || top.frame || top.plane || !top.problems.empty();
    std::vector<SensorDraft> drafts;
    drafts.reserve(features.size());
    for (FeatureScan& f : features) {
      record_crs(crs, f.feature_crs, f.draft.sensor.origin);
      record_crs(crs, f.geometry_crs, member_path(f.draft.sensor.origin, "geometry"));
      if (xy) f.draft.xy = f.position;
      else f.draft.lon_lat = LonLat{f.position.x, f.position.y};
      drafts.push_back(std::move(f.draft));
    }
    declared = top.frame;
    file_problems = std::move(top.problems);
    for (InputProblem& p : crs.problems(xy)) file_problems.push_back(std::move(p));
    return drafts;
  } catch (const FastPathMiss&) {
    return std::nullopt;
  }
}

}  // namespace covmap::io::detail
