// covmap::gis sensor reader: reported sensors from any file a planner has — covmap's CSV, sites
// JSON and GeoJSON (io/reported_sensors.h), or Point layers of any vector format GDAL reads
// (GeoPackage, Shapefile, FlatGeobuf, KML, …) — placed in the map's plane.
//
// CRS rules (docs/FORMATS.md): a GDAL layer's own CRS is used (geographic ones become WGS84
// lon/lat, projected ones x/y in that CRS), and so is a GeoJSON file's top-level "crs"; CSV x/y
// columns are in the CRS named by --sensor-crs (options.sensor_crs), or in the map's plane when
// none is named. A layer without a CRS needs --sensor-crs or a planar map. Positions then go
// through WGS84 into the map's frame (io/map_frame.h).
//
// Rejected with io::InputError naming the file (and layer): what io/reported_sensors.h rejects; a
// --sensor-crs that is not a projected CRS in metres; several layers without options.layer; a
// layer without a CRS and no --sensor-crs against a map with one; a file no reader takes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/reported_sensor.h"
#include "io/reported_sensors.h"

namespace covmap::gis {

struct SensorReadOptions {
  io::ReportedSensorOptions sensors;  // alpha, the map's frame, --planar, notes
  std::string sensor_crs;             // --sensor-crs: the CRS of CSV x/y columns; empty: none named
  std::string layer;                  // --sensor-layer: the layer of a multi-layer file
};

std::vector<ReportedSensor> read_any_sensors(const std::filesystem::path& path, const SensorReadOptions& options);

}  // namespace covmap::gis
