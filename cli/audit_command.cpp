#include "cli/audit_command.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <unistd.h>

#include "cli/audit_batch.h"
#include "cli/audit_batch_inputs.h"
#include "cli/audit_summary.h"
#include "cli/cli_support.h"
#include "job/audit_job.h"
#include "report/audit_report.h"

namespace covmap::cli {

namespace {

// A readable map file (input_file's checks and messages) or a folder that can be listed.
CLI::Validator map_file_or_folder() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::error_code ec;
        if (!std::filesystem::is_directory(text, ec)) return input_file()(text);
        if (::access(text.c_str(), R_OK | X_OK) != 0) return "cannot read the folder '" + text + "': " + std::strerror(errno);
        return "";
      },
      "MAP|FOLDER");
}

// The job library's rule for an option (job/audit_request.h), checked on the text as typed so that
// the command line and the service refuse a value in the same words.
CLI::Validator job_rule(job::AuditOption option, const std::string& shape) {
  return CLI::Validator([option](std::string& text) { return job::value_problem(option, text); }, shape);
}

}  // namespace

CLI::App* setup_audit(CLI::App& app, AuditCommandOptions& options) {
  using job::AuditOption;
  job::AuditRequest& r = options.request;
  CLI::App* cmd = app.add_subcommand("audit", "Audit a coverage map (or several, or a folder of them) against its sensors; write reports to a directory");
  cmd->add_option("maps", options.inputs,
                  "coverage map: GeoJSON or any GDAL vector layer of (Multi)Polygon cells (GeoPackage, Shapefile, "
                  "FlatGeobuf, ...), or a best-server raster (GeoTIFF, ...); lon/lat or a projected CRS. Several maps, "
                  "or a folder of them, are a batch: each map's reports in OUTDIR/<map name>/, and OUTDIR/summary.csv, "
                  "summary.json")
      ->required()
      ->check(map_file_or_folder());
  cmd->add_option("--sensors", r.inputs.sensors,
                  "reported sensors: CSV, covmap.sites/1 JSON, GeoJSON Points or any GDAL vector layer of Points "
                  "(in a batch: every map's; without it, the map DIR/NAME.EXT takes DIR/NAME.sensors.* if there is one)")
      ->check(input_file());
  cmd->add_option("--layer", r.inputs.layer, "the map's layer, in a file with several");
  cmd->add_option("--band", r.inputs.band, "raster maps: the band holding the serving sensor")
      ->check(job_rule(AuditOption::kBand, "INT in 1–65535"))
      ->capture_default_str();
  cmd->add_option("--raster-table", r.inputs.raster_table,
                  "raster maps: CSV with columns value, sensor[, name] naming the sensor of each raster value "
                  "(default: the band's attribute table, else the value is the sensor id)")
      ->check(input_file());
  cmd->add_option("--sensor-crs", r.inputs.sensor_crs,
                  "CRS of the sensor file's x/y (e.g. EPSG:2056), when the file does not declare one");
  cmd->add_option("--sensor-layer", r.inputs.sensor_layer, "the sensors' layer, in a file with several");
  cmd->add_option("--format", r.outputs.format, "GIS layers as three RFC 7946 GeoJSON files, or one GeoPackage in the map's CRS")
      ->transform(CLI::CheckedTransformer(std::map<std::string, report::GisFormat>{
          {"geojson", report::GisFormat::kGeoJson}, {"gpkg", report::GisFormat::kGeoPackage}}))
      ->default_str("geojson");
  cmd->add_option("--alpha", r.settings.alpha, "path-loss exponent (weight = 10^(P/(10·alpha))); enables dB")
      ->check(job_rule(AuditOption::kAlpha, "POSITIVE"));
  cmd->add_option("--sensor-property", r.inputs.sensor_property, "feature property naming the serving sensor")
      ->check(job_rule(AuditOption::kSensorProperty, "TEXT"))
      ->capture_default_str();
  cmd->add_flag("--planar", r.inputs.planar, "the data have no CRS and their coordinates are planar metres");
  cmd->add_option("--snap", r.settings.snap, "how far apart two cells' copies of a boundary may be (map units; 0 = estimate)")
      ->check(job_rule(AuditOption::kSnap, "NUMBER ≥ 0"));
  cmd->add_option("-o,--output", r.outputs.folder,
                  "output folder: new, empty, or one covmap wrote before (its report files are replaced together)")
      ->required();
  cmd->add_flag("--force", r.settings.force,
                "write into an existing folder covmap did not make (other files in it are left alone), "
                "and audit despite plausibility warnings");
  cmd->add_flag("--fail-on-inconsistent", options.fail_on_inconsistent,
                "exit 1 when a reported sensor is inconsistent with the map (for pipelines)");
  cmd->add_flag("-q,--quiet", options.quiet, "no progress messages");
  cmd->add_option("--threads", r.settings.threads, "threads of the refinement's covariance (the reports are the same whatever the count)")
      ->check(job_rule(AuditOption::kThreads, "INT in 1–64"))
      ->capture_default_str();
  cmd->add_option("--basemap", r.outputs.basemap_url,
                  "tile URL with {z}, {x}, {y} (e.g. https://tile.openstreetmap.org/{z}/{x}/{y}.png) that report.html "
                  "may draw under a lon/lat map when the reader switches it on; without it the page loads nothing")
      ->check(job_rule(AuditOption::kBasemap, "URL"))
      ->excludes("--planar");
  cmd->add_flag("--full-precision", r.outputs.full_precision,
                "write GeoJSON coordinates with every bit (default: 1e-8 degrees or 1 mm, what any map carries)");
  return cmd;
}

int run_audit(const AuditCommandOptions& given) {
  return guarded([&]() -> int {
    const MapList list = list_maps(given.inputs, given.request.inputs.sensors.string());
    if (list.batch) return run_audit_batch(given, list);
    AuditCommandOptions options = given;  // one map file: reports directly in OUTDIR
    options.request.inputs.map = list.maps.front().map;
    const job::AuditedMap audited = job::run_audit_job(options.request, stderr_hooks(options.quiet));
    print_audit_summary(std::cout, options.request, audited);
    return is_finding(options, audited) ? kFindings : kOk;
  });
}

}  // namespace covmap::cli
