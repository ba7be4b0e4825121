// covmap audit MAP.geojson [--sensors S] [--alpha 3.5] -o OUTDIR/: does a coverage map agree with
// the sensors that drew it? Writes report.json, report.html, sensors.geojson, shifts.geojson and diagram.geojson
// into OUTDIR (all or nothing) and prints a short summary.
// Exit 0: audited (whatever the verdicts, unless --fail-on-inconsistent: then 1 when a reported
// sensor is inconsistent); 2: bad input or an output that may not be written; 4: internal error.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace covmap::cli {

struct AuditCommandOptions {
  std::string map_path;
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
  std::string command_line;          // recorded in the reports
};

CLI::App* setup_audit(CLI::App& app, AuditCommandOptions& options);
int run_audit(const AuditCommandOptions& options);

}  // namespace covmap::cli
