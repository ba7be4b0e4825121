// Which sensor serves a best-server raster's value (internal to gis/): the value itself as the
// sensor id, or a table given with the raster — a CSV file (`--raster-table`: columns value,
// sensor and optionally name, with a header; comma, semicolon or tab) or the band's raster
// attribute table (a value column — usage MinMax or Min, or named "value" — and a sensor column:
// the one named like --sensor-property, else the one of usage Name; a "name" column gives names).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "gis/gdal_support.h"
#include "gis/map_reader.h"
#include "gis/pixel_regions.h"

namespace covmap::gis::detail {

struct RasterSensor {
  std::string id;
  std::string name;  // empty: none
};

struct RasterSensors {
  std::map<std::int64_t, RasterSensor> by_value;  // empty: the value is the id
  std::string table;                              // where the table came from, for people; empty: none
  RasterSensor of(std::int64_t value) const;
};

// Throws io::InputError naming the table (file and line, or the attribute table) for a malformed
// table: no value or sensor column, a value that is not an integer, a value listed twice, an
// empty sensor.
RasterSensors raster_sensors(GDALDatasetH ds, const MapReadOptions& options, const std::string& label);

// Throws io::InputError listing the raster values the table does not name.
void check_every_value_named(const std::vector<PixelRegions>& regions, const RasterSensors& sensors,
                             const std::string& label);

}  // namespace covmap::gis::detail
