// The two JSON syntaxes for reported sensors: covmap.sites/1 (extended) and GeoJSON Points.
#include "io/geojson_crs.h"
#include "io/reported_sensors_parsers.h"

namespace covmap::io::detail {
namespace {

// "missing x" / "x must be a number (got string \"a\")": a field problem phrased for a sensor.
std::string phrase(const FieldError& e) { return e.message == "missing" ? "missing " + e.path : e.path + " " + e.message; }

// A number member that may be left out or null; `prefix` is the object's path for messages.
std::optional<double> optional_number(const Json& object, const char* key, const std::string& prefix, SensorDraft& d) {
  const Json* value = optional_member(object, key);
  if (!value || value->is_null()) return std::nullopt;
  try {
    return number(*value, member_path(prefix, key));
  } catch (const FieldError& e) {
    d.problems.push_back(phrase(e));
    return std::nullopt;
  }
}

// The optional human name: a string, or left out or null (no name). Anything else is a problem
// rather than text made up from it: a number where a name belongs usually means shifted columns.
void read_name(const Json& object, const std::string& prefix, SensorDraft& d) {
  const Json* value = optional_member(object, "name");
  if (!value || value->is_null()) return;
  if (value->is_string()) d.sensor.name = value->get<std::string>();
  else d.problems.push_back(member_path(prefix, "name") + " must be a string (got " + describe(*value) + ")");
}

void read_strengths(const Json& object, const std::string& prefix, SensorDraft& d) {
  d.sensor.weight = optional_number(object, "weight", prefix, d);
  d.sensor.tx_power_dbm = optional_number(object, "tx_power_dbm", prefix, d);
  d.sensor.position_sigma_m = optional_number(object, "position_sigma_m", prefix, d);
  d.sensor.power_sigma_db = optional_number(object, "power_sigma_db", prefix, d);
}

// x/y or lon/lat members of a covmap.sites/1 entry.
void read_position(const Json& entry, SensorDraft& d) {
  // Both pairs may be given (vendor exports do); the map decides which one is used (finish_sensors).
  const bool planar = entry.contains("x") || entry.contains("y");
  const bool geographic = entry.contains("lon") || entry.contains("lat");
  if (!planar && !geographic) {
    d.problems.push_back("missing x and y (or lon and lat)");
    return;
  }
  try {
    if (planar) d.xy = Point{number(member(entry, "x", ""), "x"), number(member(entry, "y", ""), "y")};
    if (geographic) d.lon_lat = LonLat{number(member(entry, "lon", ""), "lon"), number(member(entry, "lat", ""), "lat")};
  } catch (const FieldError& e) {
    d.problems.push_back(phrase(e));
  }
}

// The id of a GeoJSON sensor: properties.id, else properties.sensor, else the feature's "id".
void read_geojson_id(const Json& feature, const Json* properties, SensorDraft& d) {
  const std::pair<const Json*, const char*> candidates[] = {
      {properties ? optional_member(*properties, "id") : nullptr, "properties.id"},
      {properties ? optional_member(*properties, "sensor") : nullptr, "properties.sensor"},
      {optional_member(feature, "id"), "id"}};
  for (const auto& [value, path] : candidates) {
    if (!value || value->is_null()) continue;
    try {
      d.sensor.id = site_id(*value, path);
    } catch (const FieldError& e) {
      d.problems.push_back(phrase(e));
    }
    return;
  }
  d.problems.push_back("missing id (give properties.id, properties.sensor or the feature's \"id\")");
}

void read_point(const Json& feature, bool planar, SensorDraft& d) {
  const Json* geometry = optional_member(feature, "geometry");
  if (!geometry || geometry->is_null()) {
    d.problems.push_back(std::string(geometry ? "geometry is null" : "missing geometry") + "; a sensor needs a Point");
    return;
  }
  if (!geometry->is_object()) {
    d.problems.push_back("geometry must be an object (got " + describe(*geometry) + ")");
    return;
  }
  const Json* type = optional_member(*geometry, "type");
  if (!type || *type != "Point") {
    // The name quoted as in the file, or what stands there instead.
    const std::string name = type && type->is_string() ? Json(type->get<std::string>()).dump() : type ? describe(*type) : "";
    d.problems.push_back((type ? "geometry type " + name + " is not supported" : std::string("geometry has no type")) +
                         "; a sensor is a Point");
    return;
  }
  const Json* p = optional_member(*geometry, "coordinates");
  if (!p || !p->is_array() || p->size() < 2 || !(*p)[0].is_number() || !(*p)[1].is_number()) {
    d.problems.push_back(std::string("geometry.coordinates must be ") + (planar ? "[x, y]" : "[lon, lat]") + " (got " +
                         (p ? describe(*p) : std::string("nothing")) + ")");
    return;
  }
  const double a = (*p)[0].get<double>(), b = (*p)[1].get<double>();  // altitude, if any, is ignored
  if (planar) d.xy = Point{a, b};
  else d.lon_lat = LonLat{a, b};
}

}  // namespace

std::vector<SensorDraft> parse_sensors_sites_json(const Json& root, const std::string& file) {
  check_format_tag(root, "covmap.sites/1", file);
  const auto it = root.find("sites");
  if (it == root.end()) throw InputError(file, 0, "sites", "missing");
  if (!it->is_array()) throw InputError(file, 0, "sites", "must be an array (got " + describe(*it) + ")");
  std::vector<SensorDraft> drafts;
  drafts.reserve(it->size());
  for (std::size_t i = 0; i < it->size(); ++i) {
    const Json& entry = (*it)[i];
    SensorDraft& d = drafts.emplace_back();
    d.sensor.origin = element_path("sites", i);
    if (!entry.is_object()) {
      d.problems.push_back("must be an object (got " + describe(entry) + ")");
      continue;
    }
    try {
      d.sensor.id = site_id(member(entry, "id", ""), "id");
    } catch (const FieldError& e) {
      d.problems.push_back(phrase(e));
    }
    read_name(entry, "", d);
    read_position(entry, d);
    read_strengths(entry, "", d);
  }
  return drafts;
}

std::vector<SensorDraft> parse_sensors_geojson(const Json& root, const std::string& file, bool planar, bool xy_crs,
                                               const CrsResolver& resolve, std::shared_ptr<const MapFrame>& declared,
                                               std::vector<InputProblem>& file_problems) {
  const Json* type = optional_member(root, "type");
  if (!root.is_object() || !type || *type != "FeatureCollection") {
    throw InputError(file, 0, "", "expected a GeoJSON FeatureCollection of Point features (got " +
                                      (root.is_object() ? (type ? "type " + describe(*type) : std::string("no \"type\"")) : describe(root)) +
                                      ")");
  }
  const Json* features = optional_member(root, "features");
  if (!features) throw InputError(file, 0, "features", "missing");
  if (!features->is_array()) throw InputError(file, 0, "features", "must be an array (got " + describe(*features) + ")");
  CrsDeclarations crs;
  crs.add(root, "");
  TopLevelCrs top = xy_crs ? TopLevelCrs{} : resolve_top_level(crs, resolve, planar);
  declared = top.frame;
  const bool xy = planar || xy_crs || declared || top.plane || !top.problems.empty();
  std::vector<SensorDraft> drafts;
  drafts.reserve(features->size());
  for (std::size_t i = 0; i < features->size(); ++i) {
    const Json& feature = (*features)[i];
    SensorDraft& d = drafts.emplace_back();
    d.sensor.origin = element_path("features", i);
    const Json* feature_type = optional_member(feature, "type");
    if (!feature.is_object() || !feature_type || *feature_type != "Feature") {
      d.problems.push_back("must be a GeoJSON Feature (got " +
                           (feature.is_object() ? (feature_type ? "type " + describe(*feature_type) : std::string("no \"type\""))
                                                : describe(feature)) +
                           ")");
      continue;
    }
    crs.add(feature, d.sensor.origin);
    if (const Json* geometry = optional_member(feature, "geometry"); geometry && geometry->is_object()) {
      crs.add(*geometry, member_path(d.sensor.origin, "geometry"));
    }
    const Json* properties = optional_member(feature, "properties");
    if (properties && !properties->is_null() && !properties->is_object()) {
      d.problems.push_back("properties must be an object (got " + describe(*properties) + ")");
      properties = nullptr;
    }
    if (properties && properties->is_null()) properties = nullptr;
    read_geojson_id(feature, properties, d);
    read_point(feature, xy, d);
    if (properties) {
      read_name(*properties, "properties", d);
      read_strengths(*properties, "properties", d);
    }
  }
  file_problems = std::move(top.problems);
  for (InputProblem& p : crs.problems(xy)) file_problems.push_back(std::move(p));
  return drafts;
}

}  // namespace covmap::io::detail
