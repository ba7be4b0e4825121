#include "cli/audit_command.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <unistd.h>

#include "cli/audit_batch.h"
#include "cli/audit_batch_inputs.h"
#include "cli/audit_map.h"
#include "cli/cli_support.h"
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

}  // namespace

CLI::App* setup_audit(CLI::App& app, AuditCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand("audit", "Audit a coverage map (or several, or a folder of them) against its sensors; write reports to a directory");
  cmd->add_option("maps", options.inputs,
                  "coverage map: GeoJSON or any GDAL vector layer of (Multi)Polygon cells (GeoPackage, Shapefile, "
                  "FlatGeobuf, ...), or a best-server raster (GeoTIFF, ...); lon/lat or a projected CRS. Several maps, "
                  "or a folder of them, are a batch: each map's reports in OUTDIR/<map name>/, and OUTDIR/summary.csv, "
                  "summary.json")
      ->required()
      ->check(map_file_or_folder());
  cmd->add_option("--sensors", options.sensors_path,
                  "reported sensors: CSV, covmap.sites/1 JSON, GeoJSON Points or any GDAL vector layer of Points "
                  "(in a batch: every map's; without it, the map DIR/NAME.EXT takes DIR/NAME.sensors.* if there is one)")
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

int run_audit(const AuditCommandOptions& given) {
  return guarded([&]() -> int {
    const MapList list = list_maps(given.inputs, given.sensors_path);
    if (list.batch) return run_audit_batch(given, list);
    AuditCommandOptions options = given;  // one map file: reports directly in OUTDIR
    options.map_path = list.maps.front().map;
    const AuditedMap audited = audit_map(options, stderr_progress(options.quiet));
    print_audit_summary(std::cout, options, audited);
    return is_finding(options, audited) ? kFindings : kOk;
  });
}

}  // namespace covmap::cli
