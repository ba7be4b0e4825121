// covmap::job audit requests: everything one audit needs — its inputs, its options and its outputs
// — as plain data, the one request type the command line (`covmap audit`) and the service
// (`POST /v1/audits`) both fill, and the one validator both answer with.
//
// Contract
//  - Accepted: any AuditRequest; request_problems() says what is wrong with it, option by option,
//    in words for people ("must be a positive number (got '0')"); an empty list means valid.
//  - value_problem() is the same rule applied to a value as the user typed it (command-line text,
//    or a JSON number printed back), so a value is judged alike whichever way it came.
//  - validate() throws InvalidAuditRequest naming the first problem's option; every entry point
//    that runs an audit calls it first, so no caller can skip a rule.
//  - map_read_options() and sensor_read_options() are the only mapping from a request to the GIS
//    readers (gis/map_reader.h, gis/sensor_reader.h).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gis/map_reader.h"
#include "gis/sensor_reader.h"
#include "report/audit_report.h"

namespace covmap::job {

// What is read: the coverage map and, optionally, the sensors it claims to show.
struct AuditInputs {
  std::filesystem::path map;           // any map gis/map_reader.h reads
  std::filesystem::path sensors;       // empty: no reported sensors
  std::filesystem::path raster_table;  // raster maps: CSV of raster value -> sensor; empty: none
  std::string layer;                   // the map's layer in a multi-layer file; empty: its only one
  int band = 1;                        // raster maps: the band of serving sensors, from 1
  std::string sensor_property = "sensor";  // vector maps: the property naming the serving sensor
  bool planar = false;                 // map and sensors are planar metres without a CRS
  std::string sensor_crs;              // the CRS of the sensor file's x/y when it declares none
  std::string sensor_layer;            // the sensors' layer in a multi-layer file
};

// How the audit runs.
struct AuditSettings {
  std::optional<double> alpha;  // path-loss exponent: weight = 10^(P / (10 alpha)); none: no dB
  double snap = 0.0;            // cleaning snap distance in map units; 0: estimated from the map
  int threads = 2;              // refinement threads (the reports are the same whatever the count)
  bool force = false;           // audit despite plausibility findings; write into a foreign folder
};

// What is written: the report folder, all or nothing.
struct AuditOutputs {
  std::filesystem::path folder;
  report::GisFormat format = report::GisFormat::kGeoJson;
  bool full_precision = false;  // GeoJSON coordinates with every bit, not at 1e-8 degrees / 1 mm
  std::string basemap_url;      // report.html's optional tile layer; empty: the page loads nothing
};

struct AuditRequest {
  AuditInputs inputs;
  AuditSettings settings;
  AuditOutputs outputs;
  std::string command_line;  // recorded in the reports, for the record
};

// The options a person sets, by the name the service's JSON and (with '-' for '_') the command
// line give them. A closed set: request_problems() and the service's option reader switch on it.
enum class AuditOption {
  kAlpha, kSnap, kThreads, kBand, kSensorProperty, kLayer, kSensorLayer, kSensorCrs, kPlanar, kForce,
  kFullPrecision, kBasemap, kFormat,
};
inline constexpr std::array<AuditOption, 13> kAllAuditOptions = {
    AuditOption::kAlpha,       AuditOption::kSnap,     AuditOption::kThreads,  AuditOption::kBand,
    AuditOption::kSensorProperty, AuditOption::kLayer, AuditOption::kSensorLayer, AuditOption::kSensorCrs,
    AuditOption::kPlanar,      AuditOption::kForce,    AuditOption::kFullPrecision, AuditOption::kBasemap,
    AuditOption::kFormat};

// "alpha", "snap", "threads", "band", "sensor_property", ..., "basemap", "format".
std::string_view option_name(AuditOption option);
std::optional<AuditOption> option_from_name(std::string_view name);

struct RequestProblem {
  AuditOption option = AuditOption::kAlpha;
  std::string message;  // "must be a positive number (got '0')"
};

// The rule of a numeric or text option applied to `text` as typed; empty when the value is good.
// Options without a value rule (the flags, layer names, the format) accept any text here.
std::string value_problem(AuditOption option, std::string_view text);

// Every problem of the request's options, in the order of kAllAuditOptions; empty when it may run.
std::vector<RequestProblem> request_problems(const AuditRequest& request);

// A request that may not run. `option` is the first problem's; what() is "OPTION: MESSAGE".
struct InvalidAuditRequest : std::invalid_argument {
  explicit InvalidAuditRequest(RequestProblem problem);
  RequestProblem problem;
};

// Throws InvalidAuditRequest for the first of request_problems(), if any.
void validate(const AuditRequest& request);

// How the GIS readers read this request's map and sensors.
gis::MapReadOptions map_read_options(const AuditRequest& request);
gis::SensorReadOptions sensor_read_options(const AuditRequest& request);

}  // namespace covmap::job
