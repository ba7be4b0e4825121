// sensors.geojson and diagram.geojson (docs/FORMATS.md, "Audit reports"). Geographic maps give
// RFC 7946 [lon, lat] positions; planar maps give [x, y] in the map's metres (valid GeoJSON
// syntax, but a GIS must be told the coordinates are not WGS84).
#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>

#include "report/audit_geometry.h"
#include "report/audit_json.h"
#include "report/audit_report.h"
#include "core/round_trip_numbers.h"

namespace covmap::report {
namespace {

using detail::number_or_null;
using json = detail::OrderedJson;

bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Where positions go: through `frame` to WGS84 lon/lat, or (null) the map's plane as it is; and
// whether they keep every bit (AuditRenderOptions).
struct Positions {
  const io::MapFrame* frame = nullptr;
  bool full_precision = false;
};

// WGS84 for every map with a frame, unless the map's own projected CRS is asked for.
Positions positions_for(const AuditReportContext& c) {
  const bool own_crs = c.render.crs_coordinates && c.map.frame && c.map.frame->kind() == io::FrameKind::kProjectedCrs;
  return {own_crs ? nullptr : c.map.frame.get(), c.render.full_precision};
}

// Coordinates at the precision the data carry: 1e-8 degrees (about a millimetre) or a millimetre
// in metres, unless full precision was asked for. A 17-digit coordinate only lengthens the file,
// by many times the map's own size.
// Steps per unit. Dividing the rounded count by the power of ten (not multiplying by its inverse)
// gives the double nearest the decimal, which the shortest round-trip form writes as that decimal.
constexpr double kDegreeSteps = 1e8;
constexpr double kMetreSteps = 1e3;

// The diagram's text goes to the stream in pieces of about this size.
constexpr std::size_t kFlushBytes = 1 << 20;

double rounded(double v, double steps, bool full) { return full ? v : std::round(v * steps) / steps; }

json pair(double a, double b, bool geographic, bool full) {
  const double steps = geographic ? kDegreeSteps : kMetreSteps;
  return json::array({rounded(a, steps, full), rounded(b, steps, full)});
}

// A point feature's position: lon in [-180, 180].
json point_position(Point p, const Positions& at) {
  if (!at.frame) return pair(p.x, p.y, false, at.full_precision);
  const io::LonLat g = detail::to_lonlat(*at.frame, p);
  return pair(g.lon, g.lat, true, at.full_precision);
}

// A vertex of a line or ring: lon kept continuous across the antimeridian.
json vertex_position(Point p, const Positions& at) {
  if (!at.frame) return pair(p.x, p.y, false, at.full_precision);
  const io::LonLat g = detail::to_lonlat_continuous(*at.frame, p);
  return pair(g.lon, g.lat, true, at.full_precision);
}

// The diagram layer is written as text, feature by feature: a DOM of its vertices would cost
// seconds and most of the report's memory on large maps. Same JSON as the DOM's, numbers in
// the shortest round-trip form (core/round_trip_numbers.h); a non-finite coordinate is null, as nlohmann
// writes it.
void append_coordinate(std::string& s, double v) {
  if (std::isfinite(v)) append_json_number(s, v);
  else s += "null";
}

void append_vertex(std::string& s, Point p, const Positions& at) {
  double a = p.x, b = p.y, steps = kMetreSteps;
  if (at.frame) {
    const io::LonLat g = detail::to_lonlat_continuous(*at.frame, p);
    a = g.lon, b = g.lat, steps = kDegreeSteps;
  }
  s += '[';
  append_coordinate(s, rounded(a, steps, at.full_precision));
  s += ',';
  append_coordinate(s, rounded(b, steps, at.full_precision));
  s += ']';
}

void append_ring(std::string& s, const Ring& ring, const Positions& at) {
  s += '[';
  for (const Point& p : ring) {
    append_vertex(s, p, at);
    s += ',';
  }
  append_vertex(s, ring.front(), at);  // RFC 7946: the last position repeats the first
  s += ']';
}

void append_polygon(std::string& s, const io::MapPolygon& polygon, const Positions& at) {
  s += '[';
  append_ring(s, polygon.outer, at);
  for (const Ring& hole : polygon.holes) {
    s += ',';
    append_ring(s, hole, at);
  }
  s += ']';
}

json feature(json geometry, json properties) {
  return {{"type", "Feature"}, {"geometry", std::move(geometry)}, {"properties", std::move(properties)}};
}

json sensor_properties(const audit::SensorAudit& s, const Positions& where) {
  const bool compared = s.reported && s.in_map;
  const bool sigma = s.in_map && s.uncertainty_available;
  json p = {{"kind", "sensor"},
            {"id", s.id},
            {"name", detail::name_or_null(s.name)},
            {"position_source", s.in_map ? "reconstructed" : "reported"},
            {"in_map", s.in_map},
            {"weight", s.in_map ? number_or_null(s.weight) : json()},
            {"tx_power_dbm", s.in_map ? number_or_null(s.tx_power_dbm) : json()},
            {"sigma_position_m", sigma ? number_or_null(s.sigma_position_m) : json()},
            {"sigma_log_weight", sigma ? number_or_null(s.sigma_log_weight) : json()},
            {"verdict", detail::verdict_json(s.verdict)},
            {"reason", s.reason},
            {"position_error_m", compared ? number_or_null(s.position_error_m) : json()},
            {"power_error_db", compared ? number_or_null(s.power_error_db) : json()},
            {"chi2", number_or_null(s.chi2)},
            {"iou_refined", number_or_null(s.iou_refined)},
            {"iou_reported", number_or_null(s.iou_reported)}};
  // Reported position under the names a GIS user expects for the map's coordinates.
  const char* kx = where.frame ? "reported_lon" : "reported_x";
  const char* ky = where.frame ? "reported_lat" : "reported_y";
  if (s.reported && finite(s.reported->position)) {
    const json at = point_position(s.reported->position, where);
    p[kx] = at[0];
    p[ky] = at[1];
  } else {
    p[kx] = nullptr;
    p[ky] = nullptr;
  }
  p["reported_weight"] = s.reported ? number_or_null(s.reported->weight) : json();
  p["reported_tx_power_dbm"] = s.reported ? number_or_null(s.reported->tx_power_dbm) : json();
  return p;
}

void check_options(const AuditReportContext& c, const char* who) {
  if (std::string why; !c.render.is_valid(&why)) throw std::invalid_argument(std::string(who) + ": " + why);
}

}  // namespace

void write_sensors_geojson(const AuditReportContext& c, std::ostream& out) {
  const Positions where = positions_for(c);
  check_options(c, "write_sensors_geojson");
  json features = json::array();
  for (const auto& s : c.result.sensors) {
    // Where the sensor is: reconstructed if the map has it, else where it was reported.
    std::optional<Point> at;
    if (s.in_map && finite(s.position)) at = s.position;
    if (!s.in_map && s.reported && finite(s.reported->position)) at = s.reported->position;
    json geometry = at ? json{{"type", "Point"}, {"coordinates", point_position(*at, where)}} : json();
    features.push_back(feature(std::move(geometry), sensor_properties(s, where)));
  }
  detail::write_json({{"type", "FeatureCollection"}, {"features", std::move(features)}}, out, -1);
}

void write_shifts_geojson(const AuditReportContext& c, std::ostream& out) {
  const Positions where = positions_for(c);
  check_options(c, "write_shifts_geojson");
  json features = json::array();
  for (const auto& s : c.result.sensors) {
    if (!s.in_map || !s.reported || !finite(s.position) || !finite(s.reported->position)) continue;
    json line = {{"type", "LineString"},
                 {"coordinates", json::array({vertex_position(s.reported->position, where),
                                              vertex_position(s.position, where)})}};
    features.push_back(feature(std::move(line), {{"kind", "shift"},
                                                 {"id", s.id},
                                                 {"verdict", detail::verdict_json(s.verdict)},
                                                 {"position_error_m", number_or_null(s.position_error_m)}}));
  }
  detail::write_json({{"type", "FeatureCollection"}, {"features", std::move(features)}}, out, -1);
}

void write_diagram_geojson(const AuditReportContext& c, std::ostream& out) {
  const Positions where = positions_for(c);
  check_options(c, "write_diagram_geojson");
  const Diagram& d = c.result.refined_diagram;
  const detail::ArcSampling sampling =
      detail::arc_sampling(c.render, detail::diagram_extent(d), (c.map.frame != nullptr));
  const detail::DiagramRegions regions = detail::diagram_regions(d, sampling);
  const json header = {{"type", "FeatureCollection"},
                       {"omitted_unbounded_faces", regions.unbounded_faces},
                       {"omitted_degenerate_faces", regions.degenerate_faces}};
  std::string text = header.dump();
  text.pop_back();  // the closing brace: the features follow
  text += ",\"features\":[";
  bool first = true;
  for (const auto& region : regions.regions) {
    text += first ? "" : ",";
    first = false;
    const bool multi = region.polygons.size() != 1;
    text += multi ? R"({"type":"Feature","geometry":{"type":"MultiPolygon","coordinates":[)"
                  : R"({"type":"Feature","geometry":{"type":"Polygon","coordinates":)";
    for (std::size_t k = 0; k < region.polygons.size(); ++k) {
      if (k) text += ',';
      append_polygon(text, region.polygons[k], where);
    }
    text += multi ? "]}," : "},";
    const bool known = region.site >= 0 && static_cast<std::size_t>(region.site) < d.sites.size();
    const json properties = {{"sensor", known ? json(d.sites[region.site].id) : json()},
                             {"weight", known ? number_or_null(d.sites[region.site].weight) : json()},
                             {"faces", region.polygons.size()},
                             {"orphan_faces", region.orphan_faces},
                             {"area_m2", number_or_null(region.area)}};
    text += "\"properties\":";
    text += properties.dump(-1, ' ', false, json::error_handler_t::replace);
    text += '}';
    if (text.size() > kFlushBytes) out << text, text.clear();
  }
  out << text << "]}\n";
}

}  // namespace covmap::report
