// GDAL plumbing shared by the readers and writers of gis/ (internal): one registration of the
// drivers, datasets that close themselves, GDAL's own error text for messages, and files in GDAL's
// memory file system (/vsimem/) read out as bytes.
#pragma once

#include <gdal.h>

#include <memory>
#include <string>
#include <vector>

namespace covmap::gis::detail {

// Registers GDAL's drivers once and quiets GDAL's printing to stderr (covmap says what went wrong
// itself, naming the user's file). Datasets are opened read-only and nothing is computed that GDAL
// would keep in a sidecar (.aux.xml): reading a map never changes the user's folder (sidecars are
// still read: they hold GeoTIFF raster attribute tables).
void init_gdal();

struct DatasetCloser {
  void operator()(GDALDatasetH ds) const {
    if (ds) GDALClose(ds);
  }
};
using Dataset = std::unique_ptr<std::remove_pointer_t<GDALDatasetH>, DatasetCloser>;

// Opens `path` read-only with the given GDAL_OF_* kinds; null if no driver takes it.
Dataset open_dataset(const std::string& path, unsigned kinds);

// GDAL's last error message, or `fallback` when it left none.
std::string last_gdal_error(const std::string& fallback);

// A fresh name under /vsimem/ ending in `suffix` (".geojson"), unique within the process.
std::string memory_file_name(const std::string& suffix);

// The bytes of a /vsimem/ file, which is then deleted.
std::string take_memory_file(const std::string& name);

// `text` with ASCII letters in lower case (file extensions, column names).
std::string ascii_lower(std::string text);

// The GDAL driver's short name ("GPKG", "ESRI Shapefile", "GTiff").
std::string driver_name(GDALDatasetH ds);

}  // namespace covmap::gis::detail
