// The two GDAL paths of gis/map_reader.h (internal): vector layers and best-server rasters.
#pragma once

#include <ogr_srs_api.h>

#include "gis/gdal_support.h"
#include "gis/map_reader.h"

namespace covmap::gis::detail {

// `label` names the file in messages ("cells.gpkg"); `source` receives the reader's description.
io::CoverageMap read_vector_map(GDALDatasetH ds, const std::string& label, const MapReadOptions& options,
                                MapSource& source);
io::CoverageMap read_raster_map(GDALDatasetH ds, const std::string& label, const MapReadOptions& options,
                                MapSource& source);

// One layer of a vector dataset as GeoJSON text (GDAL's ogr2ogr into memory): in WGS84 lon/lat
// when `geographic`, in the layer's own coordinates otherwise. Throws io::InputError on failure.
std::string translate_to_geojson(GDALDatasetH ds, const std::string& label, const std::string& layer, bool geographic);

// What a dataset's spatial reference makes of its coordinates.
struct DataCrs {
  enum class Kind { kNone, kGeographic, kProjected } kind = Kind::kNone;
  std::shared_ptr<const io::MapFrame> frame;  // kProjected only
  std::string name;                           // for messages
};
// Throws io::InputError for a CRS covmap cannot use (gis/crs_frame.h), for data without a CRS
// unless planar, and for planar data that declare one.
DataCrs data_crs(OGRSpatialReferenceH srs, const std::string& label, bool planar);

}  // namespace covmap::gis::detail
