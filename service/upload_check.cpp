#include "service/upload_check.h"

#include <sstream>

#include "audit/audit.h"
#include "gis/map_reader.h"
#include "gis/sensor_reader.h"
#include "io/input_error.h"
#include "io/plausibility.h"
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
  gis::MapReadOptions mo;
  mo.map.sensor_property = request.sensor_property;
  mo.map.planar = request.planar;
  mo.map.max_sensors = audit::kMaxSensors;
  mo.layer = request.layer;
  mo.band = request.band;
  io::CoverageMap coverage;
  try {
    coverage = gis::read_any_coverage_map(map, mo);
  } catch (const io::InputError& e) {
    throw as_bad_input(e, "map", map);
  }
  std::vector<ReportedSensor> reported;
  if (!sensors.empty()) {
    gis::SensorReadOptions so;
    so.sensors.alpha = request.alpha;
    so.sensors.planar = request.planar;
    so.sensors.frame = coverage.frame.get();
    so.sensor_crs = request.sensor_crs;
    so.layer = request.sensor_layer;
    try {
      reported = gis::read_any_sensors(sensors, so);
    } catch (const io::InputError& e) {
      throw as_bad_input(e, "sensors", sensors);
    }
  }
  if (request.force) return;
  if (auto finding = io::lon_lat_looking(coverage))
    throw ApiError(ErrorCode::kBadInput, *finding + " (set the option force to audit anyway)", "map");
  if (auto finding = io::sensors_far_outside(coverage, reported))
    throw ApiError(ErrorCode::kBadInput, *finding + " (set the option force to audit anyway)", "sensors");
}

}  // namespace covmap::service
