#include "cli/audit_command.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

#include "cli/cli_support.h"
#include "report/audit_report.h"
#include "io/atomic_file.h"
#include "core/readable_numbers.h"
#include "io/coverage_map.h"
#include "io/input_error.h"
#include "io/output_plan.h"
#include "io/plausibility.h"
#include "io/reported_sensors.h"
#include "gis/map_reader.h"
#include "gis/sensor_reader.h"
#include "audit/audit.h"

namespace covmap::cli {

CLI::App* setup_audit(CLI::App& app, AuditCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand("audit", "Audit a coverage map against its sensors; write reports to a directory");
  cmd->add_option("map", options.map_path,
                  "coverage map: GeoJSON or any GDAL vector layer of (Multi)Polygon cells (GeoPackage, Shapefile, "
                  "FlatGeobuf, ...), or a best-server raster (GeoTIFF, ...); lon/lat or a projected CRS")
      ->required()
      ->check(input_file());
  cmd->add_option("--sensors", options.sensors_path,
                  "reported sensors: CSV, covmap.sites/1 JSON, GeoJSON Points or any GDAL vector layer of Points")
      ->check(input_file());
  cmd->add_option("--layer", options.layer, "the map's layer, in a file with several");
  cmd->add_option("--band", options.band, "raster maps: the band holding the serving sensor")
      ->check(whole_number_in(1, 65535))
      ->capture_default_str();
  cmd->add_option("--raster-table", options.raster_table,
                  "raster maps: CSV with columns value, sensor[, name] naming the sensor of each raster value "
                  "(default: the band's attribute table, else the value is the sensor id)")
      ->check(input_file());
  cmd->add_option("--sensor-crs", options.sensor_crs,
                  "CRS of the sensor file's x/y (e.g. EPSG:2056), when the file does not declare one");
  cmd->add_option("--sensor-layer", options.sensor_layer, "the sensors' layer, in a file with several");
  cmd->add_option("--format", options.format, "GIS layers as three RFC 7946 GeoJSON files, or one GeoPackage in the map's CRS")
      ->transform(CLI::CheckedTransformer(std::map<std::string, report::GisFormat>{
          {"geojson", report::GisFormat::kGeoJson}, {"gpkg", report::GisFormat::kGeoPackage}}))
      ->default_str("geojson");
  cmd->add_option("--alpha", options.alpha, "path-loss exponent (weight = 10^(P/(10·alpha))); enables dB")
      ->check(positive_number());
  cmd->add_option("--sensor-property", options.sensor_property, "feature property naming the serving sensor")
      ->capture_default_str();
  cmd->add_flag("--planar", options.planar, "the data have no CRS and their coordinates are planar metres");
  cmd->add_option("--snap", options.snap, "how far apart two cells' copies of a boundary may be (map units; 0 = estimate)")
      ->check(non_negative_number());
  cmd->add_option("-o,--output", options.output_dir,
                  "output folder: new, empty, or one covmap wrote before (its report files are replaced together)")
      ->required();
  cmd->add_flag("--force", options.force,
                "write into an existing folder covmap did not make (other files in it are left alone), "
                "and audit despite plausibility warnings");
  cmd->add_flag("--fail-on-inconsistent", options.fail_on_inconsistent,
                "exit 1 when a reported sensor is inconsistent with the map (for pipelines)");
  cmd->add_flag("-q,--quiet", options.quiet, "no progress messages");
  cmd->add_option("--threads", options.threads, "threads of the refinement's covariance (the reports are the same whatever the count)")
      ->check(whole_number_in(1, 64))
      ->capture_default_str();
  cmd->add_option("--basemap", options.basemap_url,
                  "tile URL with {z}, {x}, {y} (e.g. https://tile.openstreetmap.org/{z}/{x}/{y}.png) that report.html "
                  "may draw under a lon/lat map when the reader switches it on; without it the page loads nothing")
      ->check([](const std::string& url) -> std::string {
        report::AuditRenderOptions render;
        render.basemap_url = url;
        std::string why;
        if (!render.is_valid(&why)) return "--basemap: " + why.substr(why.find("must"));
        if (url.rfind("https://", 0) != 0 && url.rfind("http://", 0) != 0 && url.rfind("file://", 0) != 0)
          return "--basemap: give an http://, https:// or file:// URL";
        return "";
      })
      ->excludes("--planar");
  cmd->add_flag("--full-precision", options.full_precision,
                "write GeoJSON coordinates with every bit (default: 1e-8 degrees or 1 mm, what any map carries)");
  return cmd;
}

namespace {

// Findings of io/plausibility.h stop the audit (exit 2) unless --force; with it they are warnings.
void refuse_implausible_input(const AuditCommandOptions& options, const io::CoverageMap& map,
                              const std::vector<ReportedSensor>& reported) {
  std::vector<std::pair<std::string, std::string>> doubts;  // (file, finding)
  if (auto finding = io::lon_lat_looking(map)) doubts.emplace_back(options.map_path, *finding);
  if (auto finding = io::sensors_far_outside(map, reported)) doubts.emplace_back(options.sensors_path, *finding);
  for (const auto& [file, finding] : doubts) {
    if (!options.force) throw io::InputError(file, 0, "", finding + " (pass --force to audit anyway)");
    std::cerr << "covmap audit: warning: " << file << ": " << finding << "\n";
  }
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

// One line that accounts for every sensor (the counts by verdict add up to the total), the
// agreement of the diagrams, then the sensors worth a look, by name under their verdict.
void print_summary(const AuditCommandOptions& options, const audit::AuditResult& result,
                   const report::AuditVerdictCounts& counts) {
  // A map the model does not explain is said first: the verdicts below are read in its light.
  if (result.model_fit.misfit) std::cout << options.map_path << ": " << report::model_fit_text(result) << "\n";
  std::cout << options.map_path << ": " << counts.sensors << " sensors (" << counts.in_map << " with a cell in the map, "
            << counts.sensors - counts.in_map << " reported without one; " << counts.reported << " reported): "
            << report::verdict_counts_text(counts) << "; refined diagram agrees with the map on "
            << fixed(100.0 * result.refined_agreement.mean_iou, 1) << " % of its area";
  if (result.reported_agreement)
    std::cout << " (reported sensors: " << fixed(100.0 * result.reported_agreement->mean_iou, 1) << " %)";
  std::cout << " -> " << options.output_dir << "\n";
  if (!result.model_fit.misfit && result.model_fit.known) std::cout << "  " << report::model_fit_text(result) << "\n";
  if (const std::string reach = report::reception_text(result); !reach.empty()) std::cout << "  " << reach << "\n";
  for (const audit::SensorVerdict verdict : audit::kAllSensorVerdicts) {
    if (!listed_by_name(verdict) || counts.of(verdict) == 0) continue;
    std::cout << "  " << report::verdict_words(verdict) << ":\n";
    for (const auto& s : result.sensors)
      if (s.verdict == verdict) std::cout << "    " << s.id << ": " << s.reason << "\n";
  }
}

}  // namespace

int run_audit(const AuditCommandOptions& options) {
  return guarded([&]() {
    const auto t0 = std::chrono::steady_clock::now();
    auto say = [&](const std::string& what) {
      if (options.quiet) return;
      std::cerr << "covmap audit: " << what << " ("
                << seconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()) << ")\n";
    };
    io::OutputPlan plan;
    plan.inputs = {options.map_path};
    if (!options.sensors_path.empty()) plan.inputs.push_back(options.sensors_path);
    plan.folder = options.output_dir;
    plan.folder_files = report::audit_report_file_names(options.format);
    plan.force = options.force;
    io::check_output_plan(plan);
    std::error_code size_error;
    const auto map_bytes = std::filesystem::file_size(options.map_path, size_error);
    say("reading the map (" + (size_error ? std::string("size unknown") : fixed(map_bytes / 1e6, 1) + " MB") + ")");
    gis::MapReadOptions mo;
    mo.map.sensor_property = options.sensor_property;
    mo.map.planar = options.planar;
    mo.map.max_sensors = audit::kMaxSensors;
    mo.layer = options.layer;
    mo.band = options.band;
    mo.raster_table = options.raster_table;
    gis::MapSource source;
    const io::CoverageMap map = gis::read_any_coverage_map(options.map_path, mo, &source);
    std::vector<ReportedSensor> reported;
    if (!options.sensors_path.empty()) {
      gis::SensorReadOptions so;
      so.sensors.alpha = options.alpha;
      so.sensors.planar = options.planar;
      so.sensors.frame = map.frame.get();
      so.sensor_crs = options.sensor_crs;
      so.layer = options.sensor_layer;
      std::vector<std::string> notes;  // which reading the file's sensors got, when there was a choice
      so.sensors.notes = &notes;
      reported = gis::read_any_sensors(options.sensors_path, so);
      for (const std::string& note : notes) std::cerr << "covmap audit: note: " << note << "\n";
    }
    refuse_implausible_input(options, map, reported);
    say("map read (" + source.reader + "): " + std::to_string(map.cells.size()) + " cells, " +
        std::to_string(map.vertex_count) + " vertices" +
        (map.frame ? ", in " + map.frame->description() : std::string(", planar")));
    audit::AuditOptions ao;
    ao.alpha = options.alpha;
    ao.cleaning.snap_distance = options.snap;
    ao.threads = options.threads;
    ao.progress = [&](const std::string& stage, double f) { say(stage + ", " + std::to_string(static_cast<int>(100 * f)) + " %"); };
    const audit::AuditResult result = audit::audit(map.cells, reported, ao);
    report::AuditReportContext context{result, map, options.map_path, options.sensors_path, options.alpha,
                                   options.command_line, &ao};
    context.render.basemap_url = options.basemap_url;
    context.render.full_precision = options.full_precision;
    const auto files = report::render_audit_reports(context, options.format,
                                                    [&](const std::string& file) { say("writing " + file); });
    say("moving the reports into place");
    io::write_report_folder(options.output_dir, files, options.force);
    const report::AuditVerdictCounts counts = report::count_verdicts(result.sensors);
    print_summary(options, result, counts);
    return options.fail_on_inconsistent && counts.of(audit::SensorVerdict::kInconsistent) > 0 ? kFindings : kOk;
  });
}

}  // namespace covmap::cli
