// covmap::service audit requests: the `options` part of POST /v1/audits — the audit's command-line
// options by their long names, as JSON — read, checked, and turned back into the command line the
// job's process runs.
//
//   {"alpha": 3.5, "planar": true, "sensor_property": "cell", "format": "gpkg"}
//
// Accepted members and types (docs/openapi.json lists them too): alpha (number > 0), planar,
// full_precision, force (booleans), sensor_property, layer, sensor_crs, sensor_layer, basemap
// (strings), snap (number >= 0), band (integer 1-65535), format ("geojson" | "gpkg"). Rejected with
// ApiError kBadInput naming the member: anything that is not a JSON object, an unknown member (the
// message lists the known ones), a value of the wrong type or out of range.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace covmap::service {

struct AuditRequest {
  std::optional<double> alpha;
  bool planar = false;
  bool full_precision = false;
  bool force = false;  // audit despite plausibility findings
  std::string sensor_property = "sensor";
  std::string layer;
  std::string sensor_crs;
  std::string sensor_layer;
  std::string basemap;
  double snap = 0.0;
  int band = 1;
  bool geopackage = false;  // format "gpkg"
};

// Parses the options part (empty text: all defaults).
AuditRequest parse_audit_request(std::string_view options_json);

// The arguments after the program name for `covmap audit`, reading `map` (and `sensors` if not
// empty) and writing the reports into `output_dir`.
std::vector<std::string> audit_arguments(const AuditRequest& request, const std::filesystem::path& map,
                                         const std::filesystem::path& sensors, const std::filesystem::path& output_dir);

// The report files a finished job serves under /v1/audits/{id}/NAME: those `covmap audit` writes
// for the request's format.
std::vector<std::string> report_files(const AuditRequest& request);

}  // namespace covmap::service
