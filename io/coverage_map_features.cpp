// The reference first pass of the coverage-map reader (io/coverage_map_drafts.h): the GeoJSON
// through nlohmann's DOM, every feature kept as written with the problems found on the way. It is
// the only reader that words the first pass's problems; the fast path falls back on it.
#include <cmath>
#include <string>

#include "core/round_trip_numbers.h"
#include "io/coverage_map_drafts.h"
#include "io/coverage_map_rings.h"
#include "io/input_error.h"
#include "io/input_limits.h"
#include "io/json_fields.h"
#include "io/text_util.h"

namespace covmap::io::detail {
namespace {

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

std::string pair_text(Point p) {
  std::string out(1, '(');  // appended, not "(" + ...: GCC 12 false -Wrestrict (PR 105651)
  out += round_trip_number(p.x);
  out += ", ";
  out += round_trip_number(p.y);
  out += ')';
  return out;
}

// The sensor's human name from properties.name: a string, or absent or null (no name). When the
// sensor property is itself "name", that value is the id and also the name.
void read_name(const Json& properties, const std::string& sensor_property, FeatureDraft& draft) {
  if (sensor_property == kNameProperty) {
    draft.name = draft.sensor;
    return;
  }
  const Json* value = optional_member(properties, kNameProperty);
  if (!value || value->is_null()) return;
  if (value->is_string()) draft.name = value->get<std::string>();
  else draft.problems.push_back("property " + quoted(kNameProperty) + " must be a string (got " + describe(*value) + ")");
}

// The sensor named by `property`, or a problem saying why there is none.
void read_sensor(const Json& feature, const std::string& property, FeatureDraft& draft) {
  const Json* properties = optional_member(feature, "properties");
  if (properties && !properties->is_null() && !properties->is_object()) {
    draft.problems.push_back("properties must be an object (got " + describe(*properties) + ")");
    return;
  }
  const Json* value = properties && properties->is_object() ? optional_member(*properties, property) : nullptr;
  if (!value) {
    std::string present;
    std::size_t listed = 0;
    if (properties && properties->is_object()) {
      for (const auto& [key, ignored] : properties->items()) {
        if (listed++ == 10) {
          present += ", ...";
          break;
        }
        present += (present.empty() ? "" : ", ") + quoted(key);
      }
    }
    draft.problems.push_back("missing property " + quoted(property) +
                             (present.empty() ? " (the feature has no properties)"
                                              : " (properties present: " + present + "); choose one with --sensor-property"));
    return;
  }
  try {
    draft.sensor = site_id(*value, property);
    draft.label += " (sensor " + quote_id(draft.sensor) + ")";
  } catch (const FieldError& e) {
    draft.problems.push_back("property " + quoted(property) + " " + e.message);
  }
  read_name(*properties, property, draft);
}

// Reads one ring into `out`. Stops at the first malformed position; reports lon/lat out of range
// only once per feature (`range_reported`), since a planar map would otherwise report every vertex.
// What to do about positions that are not lon/lat: --planar, or (for data that declared a
// geographic CRS) the right CRS.
std::string not_lon_lat_advice(const CoverageMapOptions& options) {
  if (options.declared_geographic_crs.empty()) return "use --planar";
  return "the data declare " + quoted(options.declared_geographic_crs) +
         ", a longitude/latitude CRS: assign the CRS the coordinates are really in (e.g. ogr2ogr -a_srs EPSG:2056)";
}

void read_ring(const Json& positions, const std::string& name, bool planar, FeatureDraft& draft, RawRing& out,
               bool& range_reported, const std::string& advice) {
  if (!positions.is_array()) {
    draft.problems.push_back(name + " must be an array of positions (got " + describe(positions) + ")");
    return;
  }
  if (positions.empty()) {
    draft.problems.push_back(name + " has no positions");
    return;
  }
  out.reserve(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Json& p = positions[i];
    // GeoJSON positions may carry altitude (and more); the map is two-dimensional.
    if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number()) {
      draft.problems.push_back(name + ", position " + std::to_string(i) + " must be " + (planar ? "[x, y]" : "[lon, lat]") +
                               " numbers (got " + (p.is_array() ? p.dump().substr(0, 60) : describe(p)) + ")");
      out.clear();
      return;
    }
    const Point q{p[0].get<double>(), p[1].get<double>()};
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) {
      draft.problems.push_back(name + ", position " + std::to_string(i) + " is not finite " + pair_text(q));
      out.clear();
      return;
    }
    if (planar && !range_reported && (std::abs(q.x) > kMaxPlanarCoordinate || std::abs(q.y) > kMaxPlanarCoordinate)) {
      draft.problems.push_back(name + ", position " + std::to_string(i) + " " + pair_text(q) + " " + kBeyondPlanarLimit);
      range_reported = true;
    }
    if (!planar && !range_reported && (std::abs(q.x) > 180.0 || std::abs(q.y) > 90.0)) {
      draft.problems.push_back(name + ", position " + std::to_string(i) + ": not a longitude/latitude; coordinates look planar (x=" +
                               round_trip_number(q.x) + ", y=" + round_trip_number(q.y) + "); " + advice);
      range_reported = true;
    }
    out.push_back(q);
  }
  if (out.front().x != out.back().x || out.front().y != out.back().y) {
    draft.problems.push_back(name + " is not closed: its last position " + std::to_string(out.size() - 1) + " " +
                             pair_text(out.back()) + " differs from position 0 " + pair_text(out.front()) +
                             "; RFC 7946 requires a ring to end where it starts");
  }
}

void read_polygon(const Json& rings, const PolygonPlace& place, bool planar, FeatureDraft& draft,
                  bool& range_reported, const std::string& advice) {
  const std::string what = place.multi ? "polygon " + std::to_string(place.polygon) : "the polygon";
  if (!rings.is_array()) {
    draft.problems.push_back(what + " must be an array of rings (got " + describe(rings) + ")");
    return;
  }
  if (rings.empty()) {
    draft.problems.push_back(what + " has no rings");
    return;
  }
  RawPolygon polygon(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    read_ring(rings[r], ring_name(place, r), planar, draft, polygon[r], range_reported, advice);
  }
  draft.polygons.push_back(std::move(polygon));
}

void read_geometry(const Json& feature, const std::string& path, bool planar, FeatureDraft& draft,
                   CrsDeclarations& crs, const std::string& advice) {
  const Json* geometry = optional_member(feature, "geometry");
  if (!geometry || geometry->is_null()) {
    draft.problems.push_back(std::string(geometry ? "geometry is null" : "missing geometry") +
                             "; each coverage cell needs a Polygon or MultiPolygon");
    return;
  }
  if (!geometry->is_object()) {
    draft.problems.push_back("geometry must be an object (got " + describe(*geometry) + ")");
    return;
  }
  crs.add(*geometry, member_path(path, "geometry"));
  const Json* type = optional_member(*geometry, "type");
  const std::string name = type && type->is_string() ? type->get<std::string>() : "";
  if (name != "Polygon" && name != "MultiPolygon") {
    draft.problems.push_back((type ? "geometry type " + (name.empty() ? describe(*type) : quoted(name))
                                   : std::string("geometry without a type")) +
                             " is not supported; a coverage map needs Polygon or MultiPolygon");
    return;
  }
  const Json* coordinates = optional_member(*geometry, "coordinates");
  if (!coordinates || !coordinates->is_array()) {
    draft.problems.push_back("geometry.coordinates " +
                             (coordinates ? "must be an array (got " + describe(*coordinates) + ")" : std::string("missing")));
    return;
  }
  bool range_reported = false;
  if (name == "Polygon") {
    read_polygon(*coordinates, {0, false}, planar, draft, range_reported, advice);
    return;
  }
  draft.multi = true;
  if (coordinates->empty()) draft.problems.push_back("the MultiPolygon has no polygons");
  for (std::size_t k = 0; k < coordinates->size(); ++k) {
    read_polygon((*coordinates)[k], {k, true}, planar, draft, range_reported, advice);
  }
}

// The first pass: every feature as written, or the reasons the file is not a coverage map at all
// (thrown at once: nothing else can be read then).
// `top` receives the frame of a CRS the file declares at its top, when options can resolve one.
std::vector<FeatureDraft> read_features(const Json& root, const std::string& file, const CoverageMapOptions& options,
                                        CrsDeclarations& crs, TopLevelCrs& top) {
  constexpr const char* kExpected = "expected a GeoJSON FeatureCollection with one Feature per coverage cell";
  if (!root.is_object()) throw InputError(file, 0, "", std::string(kExpected) + " (got " + describe(root) + ")");
  const Json* type = optional_member(root, "type");
  if (!type || *type != "FeatureCollection") {
    throw InputError(file, 0, "", std::string(kExpected) + " (got " + (type ? "type " + describe(*type) : "no \"type\"") + ")");
  }
  const Json* features = optional_member(root, "features");
  if (!features) throw InputError(file, 0, "features", "missing");
  if (!features->is_array()) throw InputError(file, 0, "features", "must be an array (got " + describe(*features) + ")");
  if (features->empty()) throw InputError(file, 0, "features", "the map has no features");
  if (features->size() > kMaxMapFeatures)
    throw InputError(file, 0, "features",
                     std::to_string(features->size()) + " features; covmap audits at most " +
                         std::to_string(kMaxMapFeatures) + " per map (docs/RELIABILITY.md): split the map into regions");
  crs.add(root, "");
  if (!options.crs_frame) top = resolve_top_level(crs, options.resolve_crs, options.planar);
  const bool planar = positions_are_xy(options, top);
  const std::string advice = not_lon_lat_advice(options);

  std::vector<FeatureDraft> drafts;
  drafts.reserve(features->size());
  for (std::size_t i = 0; i < features->size(); ++i) {
    const Json& feature = (*features)[i];
    FeatureDraft& draft = drafts.emplace_back();
    draft.index = static_cast<int>(i);
    draft.label = element_path("features", i);
    const Json* feature_type = optional_member(feature, "type");
    if (!feature.is_object() || !feature_type || *feature_type != "Feature") {
      draft.problems.push_back("must be a GeoJSON Feature (got " +
                               (feature.is_object() ? (feature_type ? "type " + describe(*feature_type) : std::string("no \"type\""))
                                                    : describe(feature)) +
                               ")");
      continue;
    }
    crs.add(feature, draft.label);
    read_sensor(feature, options.sensor_property, draft);
    read_geometry(feature, draft.label, planar, draft, crs, advice);
  }
  return drafts;
}

}  // namespace

FeatureDrafts read_features_reference(std::string_view text, const std::string& file, const CoverageMapOptions& options) {
  FeatureDrafts out;
  const Json root = parse_json(text, file);  // freed before the second pass
  out.drafts = read_features(root, file, options, out.crs, out.top);
  return out;
}

}  // namespace covmap::io::detail
