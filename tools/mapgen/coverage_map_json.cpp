#include "tools/mapgen/coverage_map_json.h"

#include "io/map_frame.h"

#include <cmath>
#include <optional>
#include <string>

namespace covmap::mapgen {
namespace {

OrderedJson position(Point p) { return OrderedJson::array({p.x, p.y}); }

OrderedJson ring_json(const Ring& ring) {
  OrderedJson out = OrderedJson::array();
  for (const auto& p : ring) out.push_back(position(p));
  return out;
}

OrderedJson polygon_json(const MapCell& cell) {
  OrderedJson out = OrderedJson::array();
  for (const auto& ring : cell.output) out.push_back(ring_json(ring));
  return out;
}

bool lonlat(const CoverageMap& map) { return map.options.frame == OutputFrame::kLonLat; }

// A marker for planar output: GeoJSON without "crs" means WGS84 lon/lat.
void add_frame(const CoverageMap& map, OrderedJson& collection) {
  if (lonlat(map)) return;
  collection["crs"] = {{"type", "name"}, {"properties", {{"name", std::string(io::kPlaneCrsName)}}}};
}

OrderedJson optional_number(const std::optional<double>& v) { return v ? OrderedJson(*v) : OrderedJson(nullptr); }

OrderedJson projection_json(const CoverageMap& map) {
  if (!map.projection) return nullptr;
  const io::LocalProjection& p = *map.projection;
  return {{"method", "transverse_mercator"},
          {"ellipsoid", "WGS84"},
          {"lon0", p.lon0()},
          {"lat0", p.lat0()},
          {"scale_factor", 1.0},
          {"false_easting_m", 0.0},
          {"false_northing_m", -p.northing0()},
          {"description", p.description()}};
}

OrderedJson gross_json(const SensorError& e) {
  if (e.gross == GrossErrorKind::kNone) return nullptr;
  OrderedJson out = {{"kind", std::string(to_string(e.gross))}};
  if (e.gross != GrossErrorKind::kPower) {
    out["position_offset_m"] = position(e.gross_offset);
    out["position_offset_distance_m"] = std::hypot(e.gross_offset.x, e.gross_offset.y);
  }
  if (e.gross != GrossErrorKind::kPosition) out["power_offset_db"] = e.gross_power_db;
  return out;
}

// The model's settings, added to "generator" for models other than the multiplicative one (whose
// truth.json keeps its original shape).
void add_model_settings(const CoverageMap& map, OrderedJson& generator) {
  const Propagation& p = map.propagation;
  if (p.model == PropagationModel::kMultiplicative) return;
  const PropagationOptions& o = map.options.propagation;
  generator["model"] = std::string(to_string(p.model));
  switch (p.model) {
    case PropagationModel::kMultiplicative: break;
    case PropagationModel::kExponents: generator["alpha_spread"] = o.alpha_spread; break;
    case PropagationModel::kExcessLoss: generator["excess_loss_max_db_per_km"] = o.excess_loss_max_db_per_km; break;
    case PropagationModel::kShadowing:
      generator["shadowing_sigma_db"] = o.shadowing_sigma_db;
      generator["shadowing_correlation_m"] = p.shadowing_correlation_m;
      generator["shadowing_amplitude_db"] = p.shadowing_amplitude_db;
      generator["shadowing_limit_db"] = p.shadowing_limit_db;
      generator["shadowing_terms"] = kShadowingTerms;
      break;
  }
  generator["sensitivity_dbm"] = optional_number(map.sensitivity_dbm);
}

// Sensor k's own propagation parameters (models other than the multiplicative one).
void add_sensor_model(const CoverageMap& map, std::size_t k, OrderedJson& sensor) {
  const Propagation& p = map.propagation;
  if (p.model == PropagationModel::kMultiplicative) return;
  const SensorPropagation& s = p.sensors[k];
  switch (p.model) {
    case PropagationModel::kMultiplicative: break;
    case PropagationModel::kExponents: sensor["alpha"] = s.alpha; break;
    case PropagationModel::kExcessLoss: sensor["excess_loss_db_per_km"] = s.excess_db_per_m * 1000.0; break;
    case PropagationModel::kShadowing: {
      OrderedJson terms = OrderedJson::array();
      for (const auto& t : s.shadowing) terms.push_back({t.kx, t.ky, t.phase});
      sensor["shadowing"] = std::move(terms);
      break;
    }
  }
}

OrderedJson layout_json(const TownLayoutRecord& r) {
  OrderedJson out = {{"kind", "towns"},
                     {"towns_file", r.towns_file},
                     {"towns_in_file", r.towns_in_file},
                     {"centre_town", r.centre_town},
                     {"weights", std::string(to_string(r.weights))}};
  if (r.weights == TownWeights::kPowerClasses) out["power_classes_dbm"] = r.power_classes_dbm;
  return out;
}

}  // namespace

OrderedJson map_geojson(const CoverageMap& map) {
  OrderedJson collection = {{"type", "FeatureCollection"}};
  add_frame(map, collection);
  OrderedJson features = OrderedJson::array();
  for (const auto& f : map.features) {
    OrderedJson geometry;
    if (f.cells.size() == 1) {
      geometry = {{"type", "Polygon"}, {"coordinates", polygon_json(f.cells[0])}};
    } else {
      OrderedJson polygons = OrderedJson::array();
      for (const auto& cell : f.cells) polygons.push_back(polygon_json(cell));
      geometry = {{"type", "MultiPolygon"}, {"coordinates", std::move(polygons)}};
    }
    const TrueSensor& t = map.truth[static_cast<std::size_t>(f.sensor)];
    OrderedJson properties = {{"sensor", t.id}};
    if (!t.name.empty()) properties["name"] = t.name;
    features.push_back({{"type", "Feature"}, {"properties", std::move(properties)}, {"geometry", std::move(geometry)}});
  }
  collection["features"] = std::move(features);
  return collection;
}

OrderedJson sensors_geojson(const CoverageMap& map) {
  OrderedJson collection = {{"type", "FeatureCollection"}};
  add_frame(map, collection);
  OrderedJson features = OrderedJson::array();
  for (std::size_t k = 0; k < map.reported.size(); ++k) {
    const ReportedSensor& r = map.reported[k];
    OrderedJson properties = {{"id", r.id}};
    if (!map.truth[k].name.empty()) properties["name"] = map.truth[k].name;  // reported in truth's order
    properties["tx_power_dbm"] = r.tx_power_dbm;
    properties["weight"] = r.weight;
    properties["position_sigma_m"] = map.options.errors.position_sigma_m;
    properties["power_sigma_db"] = map.options.errors.power_sigma_db;
    features.push_back({{"type", "Feature"},
                        {"properties", std::move(properties)},
                        {"geometry", {{"type", "Point"}, {"coordinates", position(r.output)}}}});
  }
  collection["features"] = std::move(features);
  return collection;
}

OrderedJson truth_json(const CoverageMap& map) {
  const CoverageMapOptions& o = map.options;
  const ReportErrorOptions& e = o.errors;
  OrderedJson out = {{"format", "covmap.mapgen-truth/1"}};
  out["generator"] = {{"seed", o.seed},
                      {"bin_size_m", *o.bin_size_m},
                      {"max_range_m", optional_number(o.max_range_m)},
                      {"frame", lonlat(map) ? "lonlat" : "planar"},
                      {"coordinate_digits", *o.coordinate_digits},
                      {"power_digits", o.power_digits},
                      {"vertex_jitter_m", o.vertex_jitter_m},
                      {"simplify_collinear", o.simplify_collinear},
                      {"alpha", o.alpha},
                      {"reference_power_dbm", o.reference_power_dbm},
                      {"position_sigma_m", e.position_sigma_m},
                      {"power_sigma_db", e.power_sigma_db},
                      {"gross_fraction", e.gross_fraction},
                      {"gross_position_range_m", {e.gross_position_min_m, e.gross_position_max_m}},
                      {"gross_power_range_db", {e.gross_power_min_db, e.gross_power_max_db}}};
  add_model_settings(map, out["generator"]);
  if (o.town_layout) out["layout"] = layout_json(*o.town_layout);
  out["projection"] = projection_json(map);
  const RasterGrid& g = map.raster.grid;
  out["raster"] = {{"x0", g.x0}, {"y0", g.y0}, {"bin_size_m", g.bin}, {"nx", g.nx}, {"ny", g.ny}};
  const CoverageMapCounts& c = map.counts;
  out["counts"] = {{"sensors", c.sensors},
                   {"bins", c.bins},
                   {"covered_bins", c.covered_bins},
                   {"cells", c.cells},
                   {"holes", c.holes},
                   {"vertices", c.vertices},
                   {"sensors_without_bins", c.sensors_without_bins},
                   {"gross_errors", c.gross_errors}};
  OrderedJson sensors = OrderedJson::array();
  for (std::size_t k = 0; k < map.truth.size(); ++k) {
    const TrueSensor& t = map.truth[k];
    const ReportedSensor& r = map.reported[k];
    OrderedJson s = {{"id", t.id}};
    if (!t.name.empty()) s["name"] = t.name;
    s["x"] = t.position.x;
    s["y"] = t.position.y;
    s["lon"] = t.lonlat ? OrderedJson(t.lonlat->lon) : OrderedJson(nullptr);
    s["lat"] = t.lonlat ? OrderedJson(t.lonlat->lat) : OrderedJson(nullptr);
    s["weight"] = t.weight;
    s["tx_power_dbm"] = t.tx_power_dbm;
    s["bins"] = t.bins;
    s["cells"] = t.cells;
    add_sensor_model(map, k, s);
    OrderedJson reported = {{"x", r.position.x}, {"y", r.position.y}};
    if (lonlat(map)) {
      reported["lon"] = r.output.x;
      reported["lat"] = r.output.y;
    }
    reported["tx_power_dbm"] = r.tx_power_dbm;
    reported["weight"] = r.weight;
    s["reported"] = std::move(reported);
    s["gross_error"] = gross_json(r.error);
    sensors.push_back(std::move(s));
  }
  out["sensors"] = std::move(sensors);
  return out;
}

std::string feature_collection_text(const OrderedJson& collection) {
  std::string text = "{";
  bool first = true;
  for (const auto& [key, value] : collection.items()) {
    if (!first) text += ",";
    first = false;
    text += OrderedJson(key).dump() + ":";
    if (key != "features") {
      text += value.dump();
      continue;
    }
    text += "[";
    for (std::size_t k = 0; k < value.size(); ++k) text += (k == 0 ? "\n" : ",\n") + value[k].dump();
    text += value.empty() ? "]" : "\n]";
  }
  return text + "}\n";
}

}  // namespace covmap::mapgen
