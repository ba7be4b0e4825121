#include "gis/audit_inputs.h"

#include "gis/sensor_reader.h"
#include "io/plausibility.h"

namespace covmap::gis {

io::CoverageMap read_audit_map(const std::filesystem::path& path, const AuditInputOptions& options, MapSource* source) {
  return read_any_coverage_map(path, options.map, source);
}

std::vector<ReportedSensor> read_audit_sensors(const std::filesystem::path& path, const AuditInputOptions& options,
                                               const io::CoverageMap& map, std::vector<std::string>* notes) {
  SensorReadOptions so;
  so.sensors.alpha = options.alpha;
  so.sensors.planar = options.map.map.planar;
  so.sensors.frame = map.frame.get();
  so.sensors.notes = notes;
  so.sensor_crs = options.sensor_crs;
  so.layer = options.sensor_layer;
  return read_any_sensors(path, so);
}

std::vector<ImplausibleInput> implausible_inputs(const io::CoverageMap& map, const std::vector<ReportedSensor>& reported) {
  std::vector<ImplausibleInput> found;
  if (auto finding = io::lon_lat_looking(map)) found.push_back({AuditInput::kMap, *finding});
  if (auto finding = io::sensors_far_outside(map, reported)) found.push_back({AuditInput::kSensors, *finding});
  return found;
}

}  // namespace covmap::gis
