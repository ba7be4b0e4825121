#include "report/audit_html_data.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "report/audit_html_map.h"
#include "report/audit_html_text.h"
#include "report/svg.h"

namespace covmap::report::detail {
namespace {

using Json = nlohmann::json;

// Numbers for people and for sorting: six significant digits are more than the page ever shows
// (report.json keeps every bit) and take half the bytes of a shortest round-trip double.
constexpr int kDisplayDigits = 6;

Json number(const std::optional<double>& v) {
  if (!v || !std::isfinite(*v)) return nullptr;
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", kDisplayDigits, *v);
  return std::strtod(text, nullptr);
}
Json number_if(bool known, double v) { return number(known ? std::optional<double>(v) : std::nullopt); }

Json grid_xy(const GridFrame& f, bool drawn, Point p, const char* key_x, const char* key_y, Json& into) {
  const bool ok = drawn && f.drawable(p);
  const GridPoint g = ok ? f.at(p) : GridPoint{};
  into[key_x] = ok ? Json(g.x) : Json(nullptr);
  into[key_y] = ok ? Json(g.y) : Json(nullptr);
  return into;
}

Json sensor_entry(const GridFrame& f, const audit::SensorAudit& s) {
  const bool compared = s.reported && s.in_map;
  Json j = {{"id", s.id},
            {"name", s.name},
            {"verdict", verdict_index(s.verdict)},
            {"attention", needs_attention(s.verdict)},
            {"basis", std::string(basis_words(s.basis))},
            {"colour", site_colour_for(s.id)},  // the same colour as in every --svg picture
            {"moved", number_if(compared, s.position_error_m)},
            {"sigma", number_if(s.in_map && s.uncertainty_available, s.sigma_position_m)},
            {"power_error", number(compared ? s.power_error_db : std::nullopt)},
            {"chi2", number(s.chi2)},
            {"weight", number_if(s.in_map, s.weight)},
            {"power", number(s.in_map ? s.tx_power_dbm : std::nullopt)},
            {"reported_weight", number(s.reported ? s.reported->weight : std::nullopt)},
            {"reported_power", number(s.reported ? s.reported->tx_power_dbm : std::nullopt)},
            {"iou", number(s.iou_refined)},
            {"iou_reported", number(s.iou_reported)},
            {"fit_ratio", number(s.model_fit_ratio)},
            {"reason", s.reason}};
  grid_xy(f, s.in_map, s.position, "x", "y", j);
  grid_xy(f, s.reported.has_value(), s.reported ? s.reported->position : Point{}, "rx", "ry", j);
  return j;
}

// lon/lat at the nodes of an n × n grid over the frame (for the cursor's coordinates).
Json lonlat_grid(const GridFrame& f, const io::MapFrame& projection, int n) {
  Json lon = Json::array(), lat = Json::array();
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const io::LonLat ll = projection.inverse(
          f.map_point(static_cast<double>(f.width) * i / n, static_cast<double>(f.height) * j / n));
      lon.push_back(ll.lon);
      lat.push_back(ll.lat);
    }
  }
  return {{"n", n}, {"lon", lon}, {"lat", lat}};
}

// Grid coordinates at the nodes of an n × n lon/lat grid over the frame's lon/lat extent (for
// placing the basemap's tiles).
Json basemap_grid(const GridFrame& f, const io::MapFrame& projection, int n, const std::string& url) {
  double west = 180, east = -180, south = 90, north = -90;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const io::LonLat ll = projection.inverse(
          f.map_point(static_cast<double>(f.width) * i / n, static_cast<double>(f.height) * j / n));
      west = std::min(west, ll.lon), east = std::max(east, ll.lon);
      south = std::min(south, ll.lat), north = std::max(north, ll.lat);
    }
  }
  Json x = Json::array(), y = Json::array();
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const Point p = projection.forward(west + (east - west) * i / n, north - (north - south) * j / n);
      x.push_back(std::round((p.x - f.xmin) * f.scale * 10) / 10);
      y.push_back(std::round((f.ymax - p.y) * f.scale * 10) / 10);
    }
  }
  return {{"url", url}, {"n", n}, {"west", west}, {"south", south}, {"east", east}, {"north", north}, {"x", x}, {"y", y}};
}

// '<', '>' and '&' as \u escapes (they occur only inside JSON strings), so that the text cannot
// end the <script> element it is embedded in.
std::string script_safe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (const char ch : json) {
    if (ch == '<') out += "\\u003c";
    else if (ch == '>') out += "\\u003e";
    else if (ch == '&') out += "\\u0026";
    else out += ch;
  }
  return out;
}

}  // namespace

std::string audit_page_data(const AuditReportContext& c) {
  const audit::AuditResult& r = c.result;
  const AuditRenderOptions& o = c.render;
  const GridFrame f = grid_frame(c);
  Json data;
  data["grid"] = {{"w", f.width}, {"h", f.height}, {"px", o.html_grid_px}, {"m", 1.0 / f.scale}, {"x0", f.xmin}, {"y0", f.ymax}};
  data["lonlat"] = c.map.frame ? lonlat_grid(f, *c.map.frame, o.html_lonlat_grid) : Json(nullptr);
  data["basemap"] = c.map.frame && !o.basemap_url.empty()
                        ? basemap_grid(f, *c.map.frame, o.html_lonlat_grid, o.basemap_url)
                        : Json(nullptr);
  Json verdicts = Json::array();
  for (const audit::SensorVerdict v : audit::kAllSensorVerdicts)
    verdicts.push_back({{"key", std::string(audit::to_string(v))}, {"words", std::string(verdict_words(v))}, {"colour", verdict_colour(v)}});
  data["verdicts"] = verdicts;

  const std::vector<std::size_t> order = sensors_by_severity(r.sensors);
  std::unordered_map<std::string, std::size_t> position_of;  // sensor id -> index in `order`
  // By column: each member name once rather than once per sensor (a third of the page at 10^4).
  Json columns = Json::object();
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Json entry = sensor_entry(f, r.sensors[order[k]]);
    for (const auto& [key, value] : entry.items()) columns[key].push_back(value);
    position_of.emplace(r.sensors[order[k]].id, k);
  }
  data["sensors"] = std::move(columns);

  Json cells = Json::array();
  for (const auto& cell : c.map.cells) {
    auto rings = cell_rings(f, o, cell);
    if (rings.empty()) continue;
    const auto it = position_of.find(cell.sensor);
    Json entry = Json::array({it == position_of.end() ? Json(-1) : Json(it->second)});
    for (auto& ring : rings) entry.push_back(std::move(ring));
    cells.push_back(std::move(entry));
  }
  data["cells"] = std::move(cells);
  data["boundaries"] = diagram_arcs(f, o, r.refined_diagram, false);
  data["frame"] = diagram_arcs(f, o, r.refined_diagram, true);
  data["reported_boundaries"] = r.reported_diagram ? Json(diagram_arcs(f, o, *r.reported_diagram, false)) : Json(nullptr);
  return script_safe(data.dump(-1, ' ', false, Json::error_handler_t::replace));
}

}  // namespace covmap::report::detail
