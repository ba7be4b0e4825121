// The rules every reported-sensor file is held to, whatever its syntax (see io/reported_sensors.h).
#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

#include "core/round_trip_numbers.h"
#include "io/input_limits.h"
#include "io/reported_sensors_parsers.h"
#include "io/text_util.h"

namespace covmap::io::detail {
namespace {


// "sensor 'a' (line 4)" / "sensor 'a' (features[0])": how a message refers to another sensor.
std::string reference(const SensorDraft& d) { return "sensor " + quote_id(d.sensor.id) + " (" + d.sensor.origin + ")"; }

void check_finite(double value, const char* name, SensorDraft& d) {
  if (!std::isfinite(value)) d.problems.push_back(std::string(name) + " must be finite (got " + round_trip_number(value) + ")");
}

void check_positive(const std::optional<double>& value, const char* name, SensorDraft& d) {
  if (!value) return;
  if (!std::isfinite(*value)) {
    d.problems.push_back(std::string(name) + " must be finite (got " + round_trip_number(*value) + ")");
  } else if (!(*value > 0)) {
    d.problems.push_back(std::string(name) + " must be positive (got " + round_trip_number(*value) + ")");
  }
}

void check_values(SensorDraft& d) {
  if (d.xy) {
    check_finite(d.xy->x, "x", d);
    check_finite(d.xy->y, "y", d);
    if (std::abs(d.xy->x) > kMaxPlanarCoordinate || std::abs(d.xy->y) > kMaxPlanarCoordinate)
      d.problems.push_back("position (" + round_trip_number(d.xy->x) + ", " + round_trip_number(d.xy->y) +
                           ") " + kBeyondPlanarLimit);
  }
  if (d.lon_lat) {
    const LonLat g = *d.lon_lat;
    check_finite(g.lon, "lon", d);
    check_finite(g.lat, "lat", d);
    if (std::isfinite(g.lon) && std::isfinite(g.lat) && (std::abs(g.lon) > 180.0 || std::abs(g.lat) > 90.0)) {
      d.problems.push_back("not a longitude/latitude; coordinates look planar (x=" + round_trip_number(g.lon) +
                           ", y=" + round_trip_number(g.lat) + "); use --planar with a planar map");
    }
  }
  check_positive(d.sensor.weight, "weight", d);
  if (d.sensor.tx_power_dbm) check_finite(*d.sensor.tx_power_dbm, "tx_power_dbm", d);
  check_positive(d.sensor.position_sigma_m, "position_sigma_m", d);
  check_positive(d.sensor.power_sigma_db, "power_sigma_db", d);
  if (!d.sensor.weight && !d.sensor.tx_power_dbm) d.problems.push_back("needs a weight or a tx_power_dbm");
}

// A problem about the file that names the first sensor it concerns and how many there are.
InputProblem file_problem(const std::vector<const SensorDraft*>& concerned, const std::string& message) {
  const std::size_t more = concerned.size() - 1;
  return {0, "",
          message + " (" + reference(*concerned.front()) +
              (more ? " and " + std::to_string(more) + " more sensor" + (more == 1 ? "" : "s") : std::string()) + ")"};
}

void check_unique_ids(std::vector<SensorDraft>& drafts) {
  std::unordered_map<std::string, std::size_t> first;
  for (std::size_t i = 0; i < drafts.size(); ++i) {
    if (drafts[i].sensor.id.empty()) continue;  // already reported as missing
    const auto [it, inserted] = first.emplace(drafts[i].sensor.id, i);
    if (!inserted) drafts[i].problems.push_back("duplicate id; first used by " + reference(drafts[it->second]));
  }
}

// Exact equality of the positions as read: two sensors at one point have no bisector between them.
void check_unique_positions(std::vector<SensorDraft>& drafts) {
  const auto key = [&](std::size_t i) {
    const SensorDraft& d = drafts[i];
    return d.xy ? std::tuple(0, d.xy->x, d.xy->y) : std::tuple(1, d.lon_lat->lon, d.lon_lat->lat);
  };
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < drafts.size(); ++i) {
    if (drafts[i].usable()) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::size_t run_start = 0;
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (key(order[k]) != key(order[run_start])) {
      run_start = k;
      continue;
    }
    const auto [kind, a, b] = key(order[k]);
    drafts[order[k]].problems.push_back(std::string(kind == 0 ? "same position (" : "same lon/lat (") + round_trip_number(a) +
                                        ", " + round_trip_number(b) + ") as " + reference(drafts[order[run_start]]));
  }
}

}  // namespace

std::string sensor_label(const SensorDraft& draft) {
  const std::string id = draft.sensor.id.empty() ? "" : "sensor " + quote_id(draft.sensor.id);
  if (draft.line > 0) return id.empty() ? "row" : id;
  return id.empty() ? draft.sensor.origin : draft.sensor.origin + " (" + id + ")";
}

std::vector<ReportedSensor> finish_sensors(std::vector<SensorDraft> drafts, const std::string& file,
                                           const ReportedSensorOptions& options, const MapFrame* xy_frame,
                                           std::vector<InputProblem> file_problems) {
  if (drafts.empty() && file_problems.empty()) throw InputError(file, 0, "", "no sensors");
  // Sensors that give both pairs are placed with x/y when their CRS is declared or the map is
  // planar (there is nothing else to place them with), with lon/lat otherwise; the notes say so.
  const bool use_xy = xy_frame || !options.frame;
  std::size_t both = 0;
  for (auto& d : drafts) {
    if (!d.xy || !d.lon_lat) continue;
    ++both;
    if (use_xy) d.lon_lat.reset();
    else d.xy.reset();
  }
  if (both > 0 && options.notes) {
    options.notes->push_back(file + ": " + std::to_string(both) + (both == 1 ? " sensor gives" : " sensors give") +
                             " both x/y and lon/lat; used " +
                             (xy_frame  ? "x/y, in " + xy_frame->description() + " as declared"
                              : use_xy ? std::string("x/y, as the map is planar")
                                       : std::string("lon/lat, as no CRS is declared for x/y (--sensor-crs)")));
  }
  for (auto& d : drafts) {
    if (d.usable()) check_values(d);
  }

  // Problems of the whole file, said once rather than per sensor.
  // x/y without a declared CRS are the map's plane, which only a lon/lat map cannot take; x/y in a
  // declared CRS go through WGS84, which a map without a CRS cannot take.
  const bool lon_lat_map = options.frame && options.frame->kind() == FrameKind::kLocalProjection;
  std::vector<const SensorDraft*> geographic_without_map, planar_with_geographic_map, crs_without_map, power_without_alpha;
  for (const auto& d : drafts) {
    if (!d.usable()) continue;
    if (d.lon_lat && !options.frame) geographic_without_map.push_back(&d);
    if (d.xy && !xy_frame && lon_lat_map) planar_with_geographic_map.push_back(&d);
    if (d.xy && xy_frame && !options.frame) crs_without_map.push_back(&d);
    if (!d.sensor.weight && d.sensor.tx_power_dbm && !options.alpha) power_without_alpha.push_back(&d);
  }
  if (!geographic_without_map.empty()) {
    file_problems.push_back(file_problem(geographic_without_map,
                                         "positions are lon/lat but the map is planar, so there is no projection to "
                                         "place them with; give x/y in the map's units"));
  }
  if (!planar_with_geographic_map.empty()) {
    file_problems.push_back(file_problem(planar_with_geographic_map,
                                         "positions are x/y but the map is in lon/lat; give lon/lat, name the CRS of "
                                         "the x/y with --sensor-crs (e.g. EPSG:2056), or use --planar if the map is "
                                         "planar too"));
  }
  if (!crs_without_map.empty()) {
    file_problems.push_back(file_problem(crs_without_map,
                                         "positions are x/y in " + xy_frame->description() +
                                             " but the map has no CRS, so there is no way to place them on it; give "
                                             "x/y in the map's units"));
  }
  if (!power_without_alpha.empty()) {
    file_problems.push_back(file_problem(power_without_alpha,
                                         "tx_power_dbm needs --alpha (the path-loss exponent) to become a weight"));
  }
  const bool placeable = geographic_without_map.empty() && planar_with_geographic_map.empty() && crs_without_map.empty();

  for (auto& d : drafts) {
    if (!d.usable()) continue;
    ReportedSensor& s = d.sensor;
    if (!s.weight && s.tx_power_dbm && options.alpha) {
      const double w = weight_from_power(*s.tx_power_dbm, *options.alpha);
      if (std::isfinite(w) && w > 0) {
        s.weight = w;
      } else {
        d.problems.push_back("tx_power_dbm " + round_trip_number(*s.tx_power_dbm) + " with alpha " +
                             round_trip_number(*options.alpha) + " gives weight " + round_trip_number(w) +
                             ", which is not a usable weight");
      }
    }
    if (!placeable) continue;
    if (d.xy && xy_frame) {
      const LonLat g = xy_frame->inverse(*d.xy);
      s.lon = g.lon;
      s.lat = g.lat;
      s.position = options.frame->forward(g.lon, g.lat);
      if (!std::isfinite(s.position.x) || !std::isfinite(s.position.y))
        d.problems.push_back("position (" + round_trip_number(d.xy->x) + ", " + round_trip_number(d.xy->y) + ") lies outside " +
                             xy_frame->description() + ": check the coordinates or --sensor-crs");
    } else if (d.xy) {
      s.position = *d.xy;
    } else {
      s.lon = d.lon_lat->lon;
      s.lat = d.lon_lat->lat;
      s.position = options.frame->forward(*s.lon, *s.lat);
    }
  }
  check_unique_positions(drafts);
  check_unique_ids(drafts);

  std::vector<InputProblem> problems = std::move(file_problems);
  for (const auto& d : drafts) {
    for (const auto& message : d.problems) problems.push_back({d.line, sensor_label(d), message});
  }
  if (!problems.empty()) throw InputError(file, std::move(problems));

  std::vector<ReportedSensor> out;
  out.reserve(drafts.size());
  for (auto& d : drafts) out.push_back(std::move(d.sensor));
  return out;
}

}  // namespace covmap::io::detail
