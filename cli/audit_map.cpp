#include "cli/audit_map.h"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <ostream>
#include <utility>
#include <vector>

#include "core/readable_numbers.h"
#include "gis/audit_inputs.h"
#include "io/coverage_map.h"
#include "io/input_error.h"
#include "io/output_plan.h"

namespace covmap::cli {
namespace {

// Findings of io/plausibility.h stop the audit (exit 2) unless --force; with it they are warnings.
void refuse_implausible_input(const AuditCommandOptions& options, const io::CoverageMap& map,
                              const std::vector<ReportedSensor>& reported) {
  for (const gis::ImplausibleInput& doubt : gis::implausible_inputs(map, reported)) {
    const std::string& file = doubt.input == gis::AuditInput::kMap ? options.map_path : options.sensors_path;
    if (!options.force) throw io::InputError(file, 0, "", doubt.finding + " (pass --force to audit anyway)");
    std::cerr << "covmap audit: warning: " << file << ": " << doubt.finding << "\n";
  }
}

gis::AuditInputOptions input_options(const AuditCommandOptions& options) {
  gis::AuditInputOptions o;
  o.map.map.sensor_property = options.sensor_property;
  o.map.map.planar = options.planar;
  o.map.map.max_sensors = audit::kMaxSensors;
  o.map.layer = options.layer;
  o.map.band = options.band;
  o.map.raster_table = options.raster_table;
  o.alpha = options.alpha;
  o.sensor_crs = options.sensor_crs;
  o.sensor_layer = options.sensor_layer;
  return o;
}

// Whether the summary lists the sensor by name with its reason: every verdict a planner must act on
// or look at. No default: a new verdict must be decided here (cli/ compiles with -Werror=switch).
bool listed_by_name(audit::SensorVerdict verdict) {
  switch (verdict) {
    case audit::SensorVerdict::kInconsistent:
    case audit::SensorVerdict::kUndetermined:
    case audit::SensorVerdict::kNotInMap:
    case audit::SensorVerdict::kModelMisfit: return true;
    case audit::SensorVerdict::kConsistent:
    case audit::SensorVerdict::kUnreported: return false;
  }
  return true;
}

io::CoverageMap read_map(const AuditCommandOptions& options, const AuditProgress& say, gis::MapSource& source) {
  std::error_code size_error;
  const auto map_bytes = std::filesystem::file_size(options.map_path, size_error);
  say("reading the map (" + (size_error ? std::string("size unknown") : fixed(map_bytes / 1e6, 1) + " MB") + ")");
  return gis::read_audit_map(options.map_path, input_options(options), &source);
}

std::vector<ReportedSensor> read_sensors(const AuditCommandOptions& options, const io::CoverageMap& map) {
  if (options.sensors_path.empty()) return {};
  std::vector<std::string> notes;  // which reading the file's sensors got, when there was a choice
  std::vector<ReportedSensor> reported = gis::read_audit_sensors(options.sensors_path, input_options(options), map, &notes);
  for (const std::string& note : notes) std::cerr << "covmap audit: note: " << note << "\n";
  return reported;
}

}  // namespace

AuditedMap audit_map(const AuditCommandOptions& options, const AuditProgress& progress) {
  const AuditProgress say = progress ? progress : [](const std::string&) {};
  io::OutputPlan plan;
  plan.inputs = {options.map_path};
  if (!options.sensors_path.empty()) plan.inputs.push_back(options.sensors_path);
  plan.folder = options.output_dir;
  plan.folder_files = report::audit_report_file_names(options.format);
  plan.force = options.force;
  io::check_output_plan(plan);
  gis::MapSource source;
  const auto read_start = std::chrono::steady_clock::now();
  const io::CoverageMap map = read_map(options, say, source);
  const std::vector<ReportedSensor> reported = read_sensors(options, map);
  const double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - read_start).count();
  refuse_implausible_input(options, map, reported);
  say("map read (" + source.reader + "): " + std::to_string(map.cells.size()) + " cells, " +
      std::to_string(map.vertex_count) + " vertices" +
      (map.frame ? ", in " + map.frame->description() : std::string(", planar")));
  audit::AuditOptions ao;
  ao.alpha = options.alpha;
  ao.cleaning.snap_distance = options.snap;
  ao.threads = options.threads;
  ao.progress = [&](const std::string& stage, double f) { say(stage + ", " + std::to_string(static_cast<int>(100 * f)) + " %"); };
  AuditedMap audited{audit::audit(map.cells, reported, ao), {}};
  // report.json's stage times start with reading the inputs (the reports' own writing comes after
  // report.json is made, so it is not among them).
  audited.result.timings.insert(audited.result.timings.begin(), {"reading map and sensors", read_seconds});
  audited.result.seconds += read_seconds;
  report::AuditReportContext context{audited.result, map, options.map_path, options.sensors_path, options.alpha,
                                     options.command_line, &ao};
  context.render.basemap_url = options.basemap_url;
  context.render.full_precision = options.full_precision;
  io::ReportFolderWriter folder(options.output_dir, options.force);
  report::write_audit_reports(context, options.format, folder, [&](const std::string& file) { say("writing " + file); });
  say("moving the reports into place");
  folder.commit();
  audited.counts = report::count_verdicts(audited.result.sensors);
  return audited;
}

// One line that accounts for every sensor (the counts by verdict add up to the total), the
// agreement of the diagrams, then the sensors worth a look, by name under their verdict.
void print_audit_summary(std::ostream& out, const AuditCommandOptions& options, const AuditedMap& audited) {
  const audit::AuditResult& result = audited.result;
  const report::AuditVerdictCounts& counts = audited.counts;
  // A map the model does not explain is said first: the verdicts below are read in its light.
  if (result.model_fit.misfit) out << options.map_path << ": " << report::model_fit_text(result) << "\n";
  out << options.map_path << ": " << counts.sensors << " sensors (" << counts.in_map << " with a cell in the map, "
      << counts.sensors - counts.in_map << " reported without one; " << counts.reported << " reported): "
      << report::verdict_counts_text(counts) << "; refined diagram agrees with the map on "
      << fixed(100.0 * result.refined_agreement.mean_iou, 1) << " % of its area";
  if (result.reported_agreement)
    out << " (reported sensors: " << fixed(100.0 * result.reported_agreement->mean_iou, 1) << " %)";
  out << " -> " << options.output_dir << "\n";
  if (!result.model_fit.misfit && result.model_fit.known) out << "  " << report::model_fit_text(result) << "\n";
  if (const std::string reach = report::reception_text(result); !reach.empty()) out << "  " << reach << "\n";
  for (const audit::SensorVerdict verdict : audit::kAllSensorVerdicts) {
    if (!listed_by_name(verdict) || counts.of(verdict) == 0) continue;
    out << "  " << report::verdict_words(verdict) << ":\n";
    for (const auto& s : result.sensors)
      if (s.verdict == verdict) out << "    " << s.id << ": " << s.reason << "\n";
  }
}

bool is_finding(const AuditCommandOptions& options, const AuditedMap& audited) {
  return options.fail_on_inconsistent && audited.counts.of(audit::SensorVerdict::kInconsistent) > 0;
}

AuditProgress stderr_progress(bool quiet) {
  if (quiet) return [](const std::string&) {};
  const auto t0 = std::chrono::steady_clock::now();
  return [t0](const std::string& what) {
    std::cerr << "covmap audit: " << what << " ("
              << seconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()) << ")\n";
  };
}

}  // namespace covmap::cli
