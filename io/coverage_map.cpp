// Reading a coverage map happens in two passes. The first walks the GeoJSON and keeps, per feature,
// the sensor and the rings exactly as written, checking what can be checked on the numbers as read
// (structure, closing positions, lon/lat ranges, crs). The second needs the whole map, because the
// projection centre is the centre of all vertices: it projects, then validates each polygon in the
// plane where covmap will use it (io/coverage_map_rings.h).
#include "io/coverage_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <unordered_set>

#include "io/coverage_map_rings.h"
#include "io/geojson_crs.h"
#include "io/input_error.h"
#include "io/input_limits.h"
#include "io/json_fields.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

using detail::FieldError;
using detail::Json;

using RawRing = std::vector<Point>;            // positions as written, the closing one included
using RawPolygon = std::vector<RawRing>;       // outer ring first

struct FeatureDraft {
  int index = 0;
  std::string label;  // "features[3] (sensor 'a')", or "features[3]" until the sensor is known
  std::string sensor;
  std::string name;    // properties.name, or the sensor id when that is the sensor property
  bool multi = false;  // a MultiPolygon: messages then name the polygon
  std::vector<RawPolygon> polygons;
  std::vector<std::string> problems;
};

constexpr const char* kNameProperty = "name";  // the feature property holding a sensor's human name

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

std::string pair_text(Point p) {
  std::string out(1, '(');  // appended, not "(" + ...: GCC 12 false -Wrestrict (PR 105651)
  out += detail::format_number(p.x);
  out += ", ";
  out += detail::format_number(p.y);
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
  const Json* value = detail::optional_member(properties, kNameProperty);
  if (!value || value->is_null()) return;
  if (value->is_string()) draft.name = value->get<std::string>();
  else draft.problems.push_back("property " + quoted(kNameProperty) + " must be a string (got " + detail::describe(*value) + ")");
}

// The sensor named by `property`, or a problem saying why there is none.
void read_sensor(const Json& feature, const std::string& property, FeatureDraft& draft) {
  const Json* properties = detail::optional_member(feature, "properties");
  if (properties && !properties->is_null() && !properties->is_object()) {
    draft.problems.push_back("properties must be an object (got " + detail::describe(*properties) + ")");
    return;
  }
  const Json* value = properties && properties->is_object() ? detail::optional_member(*properties, property) : nullptr;
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
    draft.sensor = detail::site_id(*value, property);
    draft.label += " (sensor " + detail::quote_id(draft.sensor) + ")";
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
    draft.problems.push_back(name + " must be an array of positions (got " + detail::describe(positions) + ")");
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
                               " numbers (got " + (p.is_array() ? p.dump().substr(0, 60) : detail::describe(p)) + ")");
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
                               detail::format_number(q.x) + ", y=" + detail::format_number(q.y) + "); " + advice);
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

void read_polygon(const Json& rings, const detail::PolygonPlace& place, bool planar, FeatureDraft& draft,
                  bool& range_reported, const std::string& advice) {
  const std::string what = place.multi ? "polygon " + std::to_string(place.polygon) : "the polygon";
  if (!rings.is_array()) {
    draft.problems.push_back(what + " must be an array of rings (got " + detail::describe(rings) + ")");
    return;
  }
  if (rings.empty()) {
    draft.problems.push_back(what + " has no rings");
    return;
  }
  RawPolygon polygon(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    read_ring(rings[r], detail::ring_name(place, r), planar, draft, polygon[r], range_reported, advice);
  }
  draft.polygons.push_back(std::move(polygon));
}

void read_geometry(const Json& feature, const std::string& path, bool planar, FeatureDraft& draft,
                   detail::CrsDeclarations& crs, const std::string& advice) {
  const Json* geometry = detail::optional_member(feature, "geometry");
  if (!geometry || geometry->is_null()) {
    draft.problems.push_back(std::string(geometry ? "geometry is null" : "missing geometry") +
                             "; each coverage cell needs a Polygon or MultiPolygon");
    return;
  }
  if (!geometry->is_object()) {
    draft.problems.push_back("geometry must be an object (got " + detail::describe(*geometry) + ")");
    return;
  }
  crs.add(*geometry, detail::member_path(path, "geometry"));
  const Json* type = detail::optional_member(*geometry, "type");
  const std::string name = type && type->is_string() ? type->get<std::string>() : "";
  if (name != "Polygon" && name != "MultiPolygon") {
    draft.problems.push_back((type ? "geometry type " + (name.empty() ? detail::describe(*type) : quoted(name))
                                   : std::string("geometry without a type")) +
                             " is not supported; a coverage map needs Polygon or MultiPolygon");
    return;
  }
  const Json* coordinates = detail::optional_member(*geometry, "coordinates");
  if (!coordinates || !coordinates->is_array()) {
    draft.problems.push_back("geometry.coordinates " +
                             (coordinates ? "must be an array (got " + detail::describe(*coordinates) + ")" : std::string("missing")));
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
                                        detail::CrsDeclarations& crs, detail::TopLevelCrs& top) {
  constexpr const char* kExpected = "expected a GeoJSON FeatureCollection with one Feature per coverage cell";
  if (!root.is_object()) throw InputError(file, 0, "", std::string(kExpected) + " (got " + detail::describe(root) + ")");
  const Json* type = detail::optional_member(root, "type");
  if (!type || *type != "FeatureCollection") {
    throw InputError(file, 0, "", std::string(kExpected) + " (got " + (type ? "type " + detail::describe(*type) : "no \"type\"") + ")");
  }
  const Json* features = detail::optional_member(root, "features");
  if (!features) throw InputError(file, 0, "features", "missing");
  if (!features->is_array()) throw InputError(file, 0, "features", "must be an array (got " + detail::describe(*features) + ")");
  if (features->empty()) throw InputError(file, 0, "features", "the map has no features");
  if (features->size() > kMaxMapFeatures)
    throw InputError(file, 0, "features",
                     std::to_string(features->size()) + " features; covmap audits at most " +
                         std::to_string(kMaxMapFeatures) + " per map (docs/RELIABILITY.md): split the map into regions");
  crs.add(root, "");
  if (!options.crs_frame) top = detail::resolve_top_level(crs, options.resolve_crs, options.planar);
  // Positions are x/y for --planar and for a declared CRS (usable or not: a refused one is reported
  // once, not again as every position out of lon/lat range), lon/lat otherwise.
  const bool planar = options.planar || options.crs_frame || top.frame || !top.problems.empty();
  const std::string advice = not_lon_lat_advice(options);

  std::vector<FeatureDraft> drafts;
  drafts.reserve(features->size());
  for (std::size_t i = 0; i < features->size(); ++i) {
    const Json& feature = (*features)[i];
    FeatureDraft& draft = drafts.emplace_back();
    draft.index = static_cast<int>(i);
    draft.label = detail::element_path("features", i);
    const Json* feature_type = detail::optional_member(feature, "type");
    if (!feature.is_object() || !feature_type || *feature_type != "Feature") {
      draft.problems.push_back("must be a GeoJSON Feature (got " +
                               (feature.is_object() ? (feature_type ? "type " + detail::describe(*feature_type) : std::string("no \"type\""))
                                                    : detail::describe(feature)) +
                               ")");
      continue;
    }
    crs.add(feature, draft.label);
    read_sensor(feature, options.sensor_property, draft);
    read_geometry(feature, draft.label, planar, draft, crs, advice);
  }
  return drafts;
}

// Centre of the shortest longitude interval holding every value, in [-180, 180). Usually the middle
// of min and max; for a map across the antimeridian (values near both -180 and 180) the interval
// wraps around, and is the complement of the widest gap between neighbouring values.
double central_longitude(std::vector<double> lons) {
  const auto [lo, hi] = std::minmax_element(lons.begin(), lons.end());
  if (*hi - *lo <= 180.0) return (*lo + *hi) / 2;
  std::sort(lons.begin(), lons.end());
  double widest = lons.front() + 360.0 - lons.back();  // the gap across the antimeridian
  std::size_t after = 0;                                // the interval starts at lons[after]
  for (std::size_t i = 1; i < lons.size(); ++i) {
    if (lons[i] - lons[i - 1] > widest) {
      widest = lons[i] - lons[i - 1];
      after = i;
    }
  }
  const double start = lons[after];
  const double end = after == 0 ? lons.back() : lons[after - 1] + 360.0;
  double centre = (start + end) / 2;
  while (centre >= 180.0) centre -= 360.0;
  return centre;
}

bool usable(const FeatureDraft& d) { return d.problems.empty(); }

// The worst |k/k_centre - 1| of a projected CRS over the bounding box of the usable vertices, on a
// grid of kScaleGridSide² points: k varies smoothly over a regional map, so the grid finds its
// extremes without asking PROJ about every vertex.
constexpr int kScaleGridSide = 17;

double crs_scale_distortion(const MapFrame& frame, const std::vector<FeatureDraft>& drafts) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const auto& d : drafts) {
    if (!usable(d)) continue;
    for (const auto& polygon : d.polygons)
      for (const auto& ring : polygon)
        for (const Point& p : ring) {
          x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
          y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        }
  }
  if (!(x0 <= x1 && y0 <= y1)) return 0.0;
  const double k_centre = frame.point_scale_at({(x0 + x1) / 2, (y0 + y1) / 2});
  double worst = 0.0;
  for (int i = 0; i < kScaleGridSide; ++i)
    for (int j = 0; j < kScaleGridSide; ++j) {
      const Point p{x0 + (x1 - x0) * i / (kScaleGridSide - 1), y0 + (y1 - y0) * j / (kScaleGridSide - 1)};
      worst = std::max(worst, std::abs(frame.point_scale_at(p) / k_centre - 1.0));
    }
  return worst;
}

LocalProjection projection_for(const std::vector<FeatureDraft>& drafts) {
  std::vector<double> lons;
  double lat_lo = std::numeric_limits<double>::infinity(), lat_hi = -lat_lo;
  for (const auto& d : drafts) {
    if (!usable(d)) continue;
    for (const auto& polygon : d.polygons) {
      for (const auto& ring : polygon) {
        for (const Point& p : ring) {
          lons.push_back(p.x);
          lat_lo = std::min(lat_lo, p.y);
          lat_hi = std::max(lat_hi, p.y);
        }
      }
    }
  }
  return LocalProjection::about(central_longitude(std::move(lons)), (lat_lo + lat_hi) / 2);
}

}  // namespace

CoverageMap parse_coverage_map(std::string_view text, const std::string& file, const CoverageMapOptions& options) {
  if (options.crs_frame && options.planar)
    throw std::invalid_argument("CoverageMapOptions: planar and a CRS frame are mutually exclusive");
  detail::CrsDeclarations crs;
  detail::TopLevelCrs top;
  std::vector<FeatureDraft> drafts;
  {
    const Json root = detail::parse_json(text, file);  // freed before the second pass
    drafts = read_features(root, file, options, crs, top);
  }
  const std::shared_ptr<const MapFrame> crs_frame = options.crs_frame ? options.crs_frame : top.frame;
  const bool crs_judged = !top.problems.empty();  // the declaration was read and refused
  if (options.max_sensors > 0) {
    std::unordered_set<std::string_view> sensors;
    for (const auto& d : drafts) sensors.insert(d.sensor);
    if (sensors.size() > options.max_sensors)
      throw InputError(file, 0, "", "the map names " + std::to_string(sensors.size()) + " sensors; one audit takes at most " +
                                        std::to_string(options.max_sensors) +
                                        " (the refinement would run for hours): split the map into regions");
  }
  std::size_t vertices = 0;
  for (const auto& d : drafts)
    for (const auto& polygon : d.polygons)
      for (const auto& ring : polygon) vertices += ring.size();
  if (vertices > kMaxMapVertices)
    throw InputError(file, 0, "",
                     std::to_string(vertices) + " vertices; covmap audits at most " + std::to_string(kMaxMapVertices) +
                         " per map (docs/RELIABILITY.md): simplify the cells or split the map into regions");
  std::vector<InputProblem> problems = std::move(top.problems);
  if (!options.crs_frame) {
    std::vector<InputProblem> declared = crs.problems(options.planar || crs_frame || crs_judged);
    problems.insert(problems.end(), declared.begin(), declared.end());
  }
  // A crs problem means the numbers are not what the reader takes them for; validating the
  // geometry of misread coordinates would only bury the one message that matters.
  const bool check_geometry = problems.empty() && std::any_of(drafts.begin(), drafts.end(), usable);

  CoverageMap map;
  // Set for lon/lat input only: the vertices are then projected, each with its point scale.
  std::optional<LocalProjection> local;
  if (check_geometry && crs_frame) {
    map.frame = crs_frame;
    map.max_scale_distortion = crs_scale_distortion(*crs_frame, drafts);
  } else if (check_geometry && !options.planar) {
    local = projection_for(drafts);
    map.frame = std::make_shared<LocalProjection>(*local);
  }
  const double k_centre = local ? local->point_scale(local->lon0(), local->lat0()) : 1.0;
  for (auto& d : drafts) {
    if (check_geometry && usable(d)) {
      MapCell cell;
      cell.sensor = d.sensor;
      cell.name = d.name;
      cell.feature = d.index;
      for (std::size_t k = 0; k < d.polygons.size(); ++k) {
        std::vector<detail::RingInput> rings;
        rings.reserve(d.polygons[k].size());
        bool projected = true;
        for (RawRing& raw : d.polygons[k]) {
          detail::RingInput& ring = rings.emplace_back();
          ring.projected.reserve(raw.size());
          for (const Point& p : raw) {
            if (!local) {
              ring.projected.push_back(p);
              continue;
            }
            const ScaledPoint q = local->forward_with_scale(p.x, p.y);
            map.max_scale_distortion = std::max(map.max_scale_distortion, std::abs(q.scale / k_centre - 1.0));
            ring.projected.push_back(q.point);
            projected = projected && std::isfinite(q.point.x) && std::isfinite(q.point.y);
          }
          ring.read = std::move(raw);
        }
        if (!projected) {
          // Only a map reaching 90 degrees of longitude from its centre gets here.
          d.problems.push_back((d.multi ? "polygon " + std::to_string(k) : std::string("the polygon")) +
                               " lies too far from the map centre for " + local->description() +
                               "; covmap audits regional maps, not continents");
          continue;
        }
        if (auto polygon = detail::make_map_polygon(rings, {k, d.multi}, d.problems)) {
          map.vertex_count += polygon->outer.size();
          for (const auto& hole : polygon->holes) map.vertex_count += hole.size();
          cell.polygons.push_back(std::move(*polygon));
        }
      }
      map.cells.push_back(std::move(cell));
    }
    for (const auto& message : d.problems) problems.push_back({0, d.label, message});
    d.polygons.clear();
    d.polygons.shrink_to_fit();
  }
  if (!problems.empty()) throw InputError(file, std::move(problems));
  return map;
}

CoverageMap read_coverage_map(const std::filesystem::path& path, const CoverageMapOptions& options) {
  return parse_coverage_map(detail::read_text_file(path), path.string(), options);
}

}  // namespace covmap::io
