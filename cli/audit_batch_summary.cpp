#include "cli/audit_batch_summary.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace covmap::cli {
namespace {

using json = nlohmann::ordered_json;

constexpr const char* kFormat = "covmap.audit-batch/1";
constexpr double kPercent = 100.0;

json number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }
json number(const std::optional<double>& value) { return value ? number(*value) : json(nullptr); }
json text_or_null(const std::string& text) { return text.empty() ? json(nullptr) : json(text); }

// The one definition of the columns (header comment): every key is present in every row.
json summary_row(const MapOutcome& m) {
  const bool audited = m.status == MapStatus::kAudited;
  const bool fit = audited && m.model_fit.known;
  json row = json::object();
  row["map"] = m.input.map;
  row["sensors_file"] = text_or_null(m.input.sensors);
  row["folder"] = m.input.folder;
  row["status"] = to_string(m.status);
  row["sensors"] = audited ? json(m.counts.sensors) : json(nullptr);
  row["in_map"] = audited ? json(m.counts.in_map) : json(nullptr);
  row["reported"] = audited ? json(m.counts.reported) : json(nullptr);
  for (const audit::SensorVerdict verdict : audit::kAllSensorVerdicts)
    row[std::string(audit::to_string(verdict))] = audited ? json(m.counts.of(verdict)) : json(nullptr);
  row["refined_agreement_percent"] = audited ? number(m.refined_agreement_percent) : json(nullptr);
  row["reported_agreement_percent"] = audited ? number(m.reported_agreement_percent) : json(nullptr);
  row["model_fit_ratio"] = fit ? number(m.model_fit.ratio) : json(nullptr);
  row["model_fit_reports_median_p"] = fit ? number(m.model_fit.reports_median_p) : json(nullptr);
  row["model_fit_misfit_sensors"] = fit ? json(m.model_fit.misfit_sensors) : json(nullptr);
  row["model_fit_misfit_area_percent"] = fit ? number(kPercent * m.model_fit.misfit_area_share) : json(nullptr);
  row["map_follows_model"] = fit ? json(!m.model_fit.misfit) : json(nullptr);
  row["error"] = text_or_null(m.error);
  return row;
}

// RFC 4180: quoted when it holds a comma, a quote or a line break; quotes doubled.
std::string csv_field(const json& value) {
  if (value.is_null()) return "";
  if (!value.is_string()) return value.dump();
  const std::string text = value.get<std::string>();
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csv_line(const json& row, bool header) {
  std::string line;
  bool first = true;
  for (const auto& [key, value] : row.items()) {
    line += (first ? "" : ",") + (header ? csv_field(json(key)) : csv_field(value));
    first = false;
  }
  return line + "\n";
}

}  // namespace

std::string_view to_string(MapStatus status) {
  switch (status) {
    case MapStatus::kAudited: return "audited";
    case MapStatus::kFailed: return "failed";
  }
  return "failed";
}

MapOutcome audited_outcome(const BatchMap& input, const job::AuditedMap& audited) {
  MapOutcome m;
  m.input = input;
  m.status = MapStatus::kAudited;
  m.counts = audited.counts;
  m.refined_agreement_percent = kPercent * audited.result.refined_agreement.mean_iou;
  if (audited.result.reported_agreement) m.reported_agreement_percent = kPercent * audited.result.reported_agreement->mean_iou;
  m.model_fit = audited.result.model_fit;
  return m;
}

MapOutcome failed_outcome(const BatchMap& input, const std::string& error) {
  MapOutcome m;
  m.input = input;
  m.status = MapStatus::kFailed;
  m.error = error;
  return m;
}

std::string summary_csv(const BatchSummary& summary) {
  std::string text = csv_line(summary_row(MapOutcome{}), true);
  for (const MapOutcome& m : summary.maps) text += csv_line(summary_row(m), false);
  return text;
}

std::string summary_json(const BatchSummary& summary) {
  json j = json::object();
  j["format"] = kFormat;
  j["command_line"] = summary.command_line;
  std::size_t audited = 0;
  for (const MapOutcome& m : summary.maps) audited += m.status == MapStatus::kAudited;
  j["maps_audited"] = audited;
  j["maps_failed"] = summary.maps.size() - audited;
  j["maps"] = json::array();
  for (const MapOutcome& m : summary.maps) j["maps"].push_back(summary_row(m));
  j["skipped"] = json::array();
  for (const SkippedFile& s : summary.skipped)
    j["skipped"].push_back({{"file", s.file}, {"reason", to_string(s.reason)}, {"why", skip_reason_words(s.reason)}});
  return j.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace covmap::cli
