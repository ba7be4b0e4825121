// The inputs of one audit, read the one way `covmap audit` and the service's upload check share:
// the coverage map in any format gis/ reads, its reported sensors placed in the map's plane, and the
// plausibility findings (io/plausibility.h) that stop an audit unless the user forces it.
//
// Contract:
//   - read_audit_map / read_audit_sensors: as read_any_coverage_map / read_any_sensors with the
//     options built from AuditInputOptions (the sensors through the map's frame, --planar for both).
//     Bad input throws io::InputError naming the file and item; the callers say it their way
//     (exit 2, or an HTTP 400 naming the upload's part).
//   - implausible_inputs: every finding, each with the input it is about; empty when none. What a
//     caller does with them (refuse, or warn under --force) is its own.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/reported_sensor.h"
#include "gis/map_reader.h"
#include "io/coverage_map.h"

namespace covmap::gis {

struct AuditInputOptions {
  MapReadOptions map;               // --sensor-property, --planar, the sensor limit, --layer, --band, --raster-table
  std::optional<double> alpha;      // path-loss exponent of the sensors' powers
  std::string sensor_crs;           // --sensor-crs
  std::string sensor_layer;         // --sensor-layer
};

io::CoverageMap read_audit_map(const std::filesystem::path& path, const AuditInputOptions& options,
                               MapSource* source = nullptr);

// notes (may be null) receives which reading the file got where there was a choice.
std::vector<ReportedSensor> read_audit_sensors(const std::filesystem::path& path, const AuditInputOptions& options,
                                               const io::CoverageMap& map, std::vector<std::string>* notes = nullptr);

enum class AuditInput { kMap, kSensors };

struct ImplausibleInput {
  AuditInput input = AuditInput::kMap;
  std::string finding;
};

std::vector<ImplausibleInput> implausible_inputs(const io::CoverageMap& map, const std::vector<ReportedSensor>& reported);

}  // namespace covmap::gis
