// report.json, format covmap.audit/1 (docs/FORMATS.md, "Audit reports"). Every member is always
// present, null when it does not apply, so that a program reading many reports sees one shape.
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "report/audit_geometry.h"
#include "report/audit_json.h"
#include "report/audit_report.h"

namespace covmap::report {
namespace {

using detail::name_or_null;
using detail::number_or_null;
using json = detail::OrderedJson;

json string_list(const std::vector<std::string>& items) {
  json a = json::array();
  for (const auto& s : items) a.push_back(s);
  return a;
}

// x, y always; lon, lat when the map is geographic (null otherwise).
void put_position(json& j, Point p, const io::CoverageMap& map) {
  j["x"] = number_or_null(p.x);
  j["y"] = number_or_null(p.y);
  if (map.frame && std::isfinite(p.x) && std::isfinite(p.y)) {
    const io::LonLat g = detail::to_lonlat(*map.frame, p);
    j["lon"] = number_or_null(g.lon);
    j["lat"] = number_or_null(g.lat);
  } else {
    j["lon"] = nullptr;
    j["lat"] = nullptr;
  }
}

json reported_json(const ReportedSensor& r, const io::CoverageMap& map) {
  json j = json::object();
  j["name"] = name_or_null(r.name);
  put_position(j, r.position, map);
  j["weight"] = number_or_null(r.weight);
  j["tx_power_dbm"] = number_or_null(r.tx_power_dbm);
  j["position_sigma_m"] = number_or_null(r.position_sigma_m);
  j["power_sigma_db"] = number_or_null(r.power_sigma_db);
  return j;
}

json sensor_json(const audit::SensorAudit& s, const io::CoverageMap& map) {
  json j = json::object();
  j["id"] = s.id;
  j["name"] = name_or_null(s.name);
  j["in_map"] = s.in_map;
  // A sensor only reported has no reconstruction: its reconstructed members are null.
  const bool rebuilt = s.in_map;
  if (rebuilt) {
    put_position(j, s.position, map);
  } else {
    for (const char* key : {"x", "y", "lon", "lat"}) j[key] = nullptr;
  }
  j["weight"] = rebuilt ? number_or_null(s.weight) : json();
  j["tx_power_dbm"] = rebuilt ? number_or_null(s.tx_power_dbm) : json();
  j["relative_power_db"] = rebuilt ? number_or_null(s.relative_power_db) : json();
  const bool sigma = rebuilt && s.uncertainty_available;
  j["uncertainty_available"] = sigma;
  j["sigma_x_m"] = sigma ? number_or_null(s.sigma_x) : json();
  j["sigma_y_m"] = sigma ? number_or_null(s.sigma_y) : json();
  j["cov_xy_m2"] = sigma ? number_or_null(s.cov_xy) : json();
  j["sigma_position_m"] = sigma ? number_or_null(s.sigma_position_m) : json();
  j["sigma_log_weight"] = sigma ? number_or_null(s.sigma_log_weight) : json();
  j["reported"] = s.reported ? reported_json(*s.reported, map) : json();
  const bool compared = s.reported && s.in_map;
  j["position_error_m"] = compared ? number_or_null(s.position_error_m) : json();
  j["power_error_db"] = compared ? number_or_null(s.power_error_db) : json();
  j["weight_ratio"] = compared ? number_or_null(s.weight_ratio) : json();
  j["chi2"] = number_or_null(s.chi2);  // null unless the verdict was reached by the χ² test
  j["verdict_basis"] = s.basis == audit::VerdictBasis::kNone ? json() : json(std::string(audit::to_string(s.basis)));
  j["model_fit_ratio"] = s.model_fit_ratio ? number_or_null(*s.model_fit_ratio) : json();
  j["verdict"] = detail::verdict_json(s.verdict);
  j["reason"] = s.reason;
  j["iou_refined"] = number_or_null(s.iou_refined);
  j["iou_reported"] = number_or_null(s.iou_reported);
  return j;
}

json agreement_json(const audit::DiagramAgreement& a) {
  return {{"mean_iou", number_or_null(a.mean_iou)},
          {"hausdorff_m", number_or_null(a.hausdorff_m)},
          {"vanished", string_list(a.vanished)},
          {"appeared", string_list(a.appeared)}};
}

json cleaning_json(const cleaning::CleaningReport& r) {
  return {{"snap_distance_m", number_or_null(r.snap_distance)},
          {"bin_size_estimate_m", number_or_null(r.bin_size_estimate)},
          {"input_vertices", r.input_vertices},
          {"cells", r.cells},
          {"sensors", r.sensors},
          {"chains", r.chains},
          {"frame_chains", r.frame_chains},
          {"range_edges", r.range_edges},
          {"junctions", r.junctions},
          {"junctions_merged", r.junctions_merged},
          {"gaps_closed", r.gaps_closed},
          {"overlaps_resolved", r.overlaps_resolved},
          {"short_chains_dropped", r.short_chains_dropped},
          {"nodes_snapped", r.nodes_snapped},
          {"repairs", cleaning_repairs(r)}};
}

json thresholds_json(const audit::AuditOptions& o, double bin_size_m) {
  return {{"inconsistency_chi2", number_or_null(o.inconsistency_chi2)},
          {"position_floor_bins", number_or_null(o.position_floor_bins)},
          {"position_floor_m", number_or_null(o.position_floor_bins * bin_size_m)},
          {"power_floor_db", number_or_null(o.power_floor_db)},
          {"snap_distance_m", number_or_null(o.cleaning.snap_distance)},
          {"min_chain_length", number_or_null(o.cleaning.min_chain_length)},
          {"line_preference", number_or_null(o.cleaning.line_preference)}};
}

// "lonlat" (projected by covmap), "projected" (the data's own CRS), "planar" (no CRS).
const char* coordinates_name(const io::CoverageMap& map) {
  if (!map.frame) return "planar";
  switch (map.frame->kind()) {
    case io::FrameKind::kLocalProjection: return "lonlat";
    case io::FrameKind::kProjectedCrs: return "projected";
  }
  return "planar";
}

json map_json(const AuditReportContext& c) {
  json j = {{"file", c.map_file},
            {"coordinates", coordinates_name(c.map)},
            {"cells", c.map.cells.size()},
            {"vertices", c.map.vertex_count}};
  if (c.map.frame) {
    j["projection"] = {{"description", c.map.frame->description()},
                       {"crs", c.map.frame->crs_code().empty() ? json(nullptr) : json(c.map.frame->crs_code())},
                       {"lon0", number_or_null(c.map.frame->reference().lon)},
                       {"lat0", number_or_null(c.map.frame->reference().lat)},
                       {"max_scale_distortion", number_or_null(c.map.max_scale_distortion)}};
  } else {
    j["projection"] = nullptr;
  }
  return j;
}

// Every sensor counted once: the totals, then every verdict of audit::kAllSensorVerdicts under its
// report name, so the verdict counts add up to "sensors".
json summary_json(const AuditVerdictCounts& counts) {
  json j = {{"sensors", counts.sensors}, {"in_map", counts.in_map}, {"reported", counts.reported}};
  for (std::size_t i = 0; i < counts.by_verdict.size(); ++i)
    j[std::string(audit::to_string(audit::kAllSensorVerdicts[i]))] = counts.by_verdict[i];
  return j;
}

// The reception limit, null when the map has no range edges.
json reception_json(const std::optional<audit::ReceptionLimit>& limit) {
  if (!limit) return nullptr;
  return {{"range_m", number_or_null(limit->range_m)},
          {"range_sigma_m", number_or_null(limit->range_sigma_m)},
          {"sensitivity_dbm", limit->sensitivity_dbm ? number_or_null(*limit->sensitivity_dbm) : json()},
          {"sensors", limit->sensors}};
}

// How well the multiplicative model explains the map, null when not measured.
json model_fit_json(const audit::ModelFit& fit) {
  if (!fit.known) return nullptr;
  return {{"ratio", number_or_null(fit.ratio)},
          {"reports_median_p", fit.reports_median_p ? number_or_null(*fit.reports_median_p) : json()},
          {"misfit", fit.misfit},
          {"misfit_sensors", fit.misfit_sensors},
          {"misfit_area_share", number_or_null(fit.misfit_area_share)}};
}

// Wall-clock times, the one member that differs between runs of the same input.
json timings_json(const audit::AuditResult& r) {
  json stages = json::array();
  for (const audit::StageTiming& t : r.timings) stages.push_back({{"stage", t.stage}, {"seconds", number_or_null(t.seconds)}});
  return {{"seconds", number_or_null(r.seconds)}, {"stages", std::move(stages)}};
}

}  // namespace

void write_audit_json(const AuditReportContext& c, std::ostream& out) {
  if (std::string why; !c.render.is_valid(&why)) throw std::invalid_argument("write_audit_json: " + why);
  const audit::AuditResult& r = c.result;
  json j = json::object();
  j["format"] = "covmap.audit/1";
  j["command_line"] = c.command_line;
  j["map"] = map_json(c);
  j["sensors_file"] = c.sensors_file.empty() ? json() : json(c.sensors_file);
  j["alpha"] = number_or_null(c.alpha);
  j["summary"] = summary_json(count_verdicts(r.sensors));
  j["cleaning"] = cleaning_json(r.cleaned.report);
  j["bin_size_m"] = number_or_null(r.bin_size_m);
  j["boundary_samples"] = r.boundary_samples;
  j["refinement"] = r.refinement_summary;
  j["reception"] = reception_json(r.reception);
  j["model_fit"] = model_fit_json(r.model_fit);
  j["alpha_estimate"] = r.alpha_estimate ? json{{"low", number_or_null(r.alpha_estimate->low)},
                                                {"sigma_low", number_or_null(r.alpha_estimate->sigma_low)},
                                                {"high", number_or_null(r.alpha_estimate->high)},
                                                {"sigma_high", number_or_null(r.alpha_estimate->sigma_high)},
                                                {"sensors", r.alpha_estimate->sensors},
                                                {"outliers", r.alpha_estimate->outliers},
                                                {"given", c.alpha ? json(*c.alpha) : json()},
                                                {"disagrees", r.alpha_estimate->disagrees}}
                                         : json();
  j["agreement"] = {{"refined", agreement_json(r.refined_agreement)},
                    {"reported", r.reported_agreement ? agreement_json(*r.reported_agreement) : json()}};
  j["thresholds"] = c.options ? thresholds_json(*c.options, r.bin_size_m) : json();
  j["messages"] = string_list(r.messages);
  j["timings"] = timings_json(r);
  j["sensors"] = json::array();
  for (const auto& s : r.sensors) j["sensors"].push_back(sensor_json(s, c.map));
  detail::write_json(j, out, 1);
}

std::string verdict_counts_json(const AuditVerdictCounts& counts) { return summary_json(counts).dump(); }

}  // namespace covmap::report
