#include "service/upload_check.h"

#include <sstream>

#include "audit/audit.h"
#include "gis/audit_inputs.h"
#include "io/input_error.h"
#include "service/api_error.h"

namespace covmap::service {
namespace {

// An InputError as the API says it: the message without the file's path on the server (the user
// knows it as "map" or "sensors"), `where` naming the part and the item.
ApiError as_bad_input(const io::InputError& e, const std::string& part, const std::filesystem::path& path) {
  std::string message = e.what();
  const std::string server_path = path.string();
  for (std::size_t at; (at = message.find(server_path)) != std::string::npos;) message.replace(at, server_path.size(), part);
  std::string where = part;
  if (!e.problems.empty() && !e.problems.front().item.empty()) where += ": " + e.problems.front().item;
  return ApiError(ErrorCode::kBadInput, message, where);
}

}  // namespace

void check_audit_inputs(const AuditRequest& request, const std::filesystem::path& map,
                        const std::filesystem::path& sensors) {
  gis::AuditInputOptions options;
  options.map.map.sensor_property = request.sensor_property;
  options.map.map.planar = request.planar;
  options.map.map.max_sensors = audit::kMaxSensors;
  options.map.layer = request.layer;
  options.map.band = request.band;
  options.alpha = request.alpha;
  options.sensor_crs = request.sensor_crs;
  options.sensor_layer = request.sensor_layer;
  io::CoverageMap coverage;
  try {
    coverage = gis::read_audit_map(map, options);
  } catch (const io::InputError& e) {
    throw as_bad_input(e, "map", map);
  }
  std::vector<ReportedSensor> reported;
  if (!sensors.empty()) {
    try {
      reported = gis::read_audit_sensors(sensors, options, coverage);
    } catch (const io::InputError& e) {
      throw as_bad_input(e, "sensors", sensors);
    }
  }
  if (request.force) return;
  for (const gis::ImplausibleInput& doubt : gis::implausible_inputs(coverage, reported))
    throw ApiError(ErrorCode::kBadInput, doubt.finding + " (set the option force to audit anyway)",
                   doubt.input == gis::AuditInput::kMap ? "map" : "sensors");
}

}  // namespace covmap::service
