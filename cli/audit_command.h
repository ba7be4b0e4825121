// covmap audit MAP [--sensors S] [--alpha 3.5] -o OUTDIR/: does a coverage map agree with the
// sensors that drew it? MAP is GeoJSON, any GDAL vector layer or a best-server raster, in lon/lat
// or a projected CRS (gis/map_reader.h). Writes report.json, report.html and the GIS layers —
// sensors.geojson, shifts.geojson and diagram.geojson, or with --format gpkg one audit.gpkg in the
// map's CRS — into OUTDIR (all or nothing) and prints a short summary (cli/audit_map.h).
// covmap audit MAP1 MAP2 ... | FOLDER -o OUTDIR/: a batch, each map's reports in OUTDIR/<map>/ and
// a summary table beside them (cli/audit_batch.h).
// Exit 0: audited (whatever the verdicts, unless --fail-on-inconsistent: then 1 when a reported
// sensor is inconsistent); 2: bad input or an output that may not be written (in a batch: any map
// failed); 4: internal error.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "report/audit_report.h"

namespace covmap::cli {

struct AuditCommandOptions {
  std::vector<std::string> inputs;   // the MAP and FOLDER arguments as typed (cli/audit_batch_inputs.h)
  std::string map_path;              // the map audited: set by run_audit from inputs, per map in a batch
  std::string sensors_path;          // empty: no reported sensors
  std::string output_dir;
  std::optional<double> alpha;       // path-loss exponent: weight = 10^(P / (10 alpha))
  std::string sensor_property = "sensor";
  bool planar = false;               // map and sensors in planar metres, not lon/lat
  double snap = 0.0;                 // cleaning snap distance (0: estimated)
  bool quiet = false;                // no progress on stderr
  bool force = false;                // write into a foreign folder; audit despite plausibility warnings
  bool fail_on_inconsistent = false; // exit 1 when a reported sensor is inconsistent
  int threads = 2;                   // covariance threads (same reports whatever the count)
  std::string basemap_url;           // report.html's optional tile layer (empty: none, the page stays offline)
  bool full_precision = false;       // GeoJSON coordinates with every bit, not at 1e-8 degrees / 1 mm
  std::string layer;                 // --layer: the map's layer in a multi-layer file
  int band = 1;                      // --band: the raster band of serving sensors
  std::string raster_table;          // --raster-table: CSV of raster value -> sensor
  std::string sensor_crs;            // --sensor-crs: the CRS of the sensor file's x/y
  std::string sensor_layer;          // --sensor-layer: the sensors' layer in a multi-layer file
  report::GisFormat format = report::GisFormat::kGeoJson;  // --format: how the GIS layers are written
  std::string command_line;          // recorded in the reports
};

CLI::App* setup_audit(CLI::App& app, AuditCommandOptions& options);
int run_audit(const AuditCommandOptions& options);

}  // namespace covmap::cli
