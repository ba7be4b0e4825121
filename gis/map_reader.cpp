#include "gis/map_reader.h"

#include <algorithm>
#include <fstream>

#include "gis/crs_frame.h"
#include "gis/map_readers.h"
#include "io/input_error.h"

namespace covmap::gis {
namespace {

// GeoJSON by name, or by content for files named otherwise (a JSON text starts with '{').
bool is_geojson(const std::filesystem::path& path) {
  const std::string ext = detail::ascii_lower(path.extension().string());
  if (ext == ".geojson" || ext == ".json") return true;
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c) && (c == ' ' || c == '\t' || c == '\r' || c == '\n')) {
  }
  return in && c == '{';
}

}  // namespace

io::CoverageMap read_any_coverage_map(const std::filesystem::path& path, const MapReadOptions& options,
                                      MapSource* source) {
  const std::string label = path.string();
  MapSource ignored;
  MapSource& said = source ? *source : ignored;
  if (is_geojson(path)) {
    io::CoverageMapOptions map_options = options.map;
    if (!map_options.crs_frame) map_options.resolve_crs = proj_crs_resolver();
    said.reader = "GeoJSON";
    return io::read_coverage_map(path, map_options);
  }
  const detail::Dataset ds = detail::open_dataset(label, GDAL_OF_VECTOR | GDAL_OF_RASTER);
  if (!ds)
    throw io::InputError(label, 0, "",
                         "neither covmap nor GDAL reads this file as a map (" + detail::last_gdal_error("no driver took it") +
                             "); export the coverage map as GeoJSON, GeoPackage, Shapefile, FlatGeobuf or a GeoTIFF "
                             "best-server raster (docs/FORMATS.md lists every format)");
  if (GDALDatasetGetLayerCount(ds.get()) > 0) return detail::read_vector_map(ds.get(), label, options, said);
  if (GDALGetRasterCount(ds.get()) > 0) return detail::read_raster_map(ds.get(), label, options, said);
  throw io::InputError(label, 0, "", "GDAL opens the file (" + detail::driver_name(ds.get()) +
                                         ") but finds neither vector layers nor raster bands in it");
}

}  // namespace covmap::gis
