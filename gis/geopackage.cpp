#include "gis/geopackage.h"

#include <gdal_utils.h>

#include <stdexcept>

#include "gis/gdal_support.h"

namespace covmap::gis {
namespace {

const char* geometry_name(LayerGeometry geometry) {
  switch (geometry) {
    case LayerGeometry::kPoint: return "POINT";
    case LayerGeometry::kLineString: return "LINESTRING";
    case LayerGeometry::kMultiPolygon: return "MULTIPOLYGON";
  }
  return "GEOMETRY";
}

// Appends one GeoJSON text as a table of `target` through GDAL's ogr2ogr (GDALVectorTranslate).
void append_layer(GDALDatasetH target, const GeoJsonLayer& layer, const std::string& crs) {
  const std::string source_name = detail::memory_file_name(".geojson");
  VSILFILE* f = VSIFileFromMemBuffer(source_name.c_str(),
                                     reinterpret_cast<GByte*>(const_cast<char*>(layer.geojson.data())),
                                     layer.geojson.size(), FALSE);
  if (f) VSIFCloseL(f);
  detail::Dataset source = detail::open_dataset(source_name, GDAL_OF_VECTOR);
  if (!source) {
    VSIUnlink(source_name.c_str());
    throw std::runtime_error("GDAL cannot read the " + layer.name + " layer: " + detail::last_gdal_error("no reason given"));
  }
  // One geometry type per table, declared, which every GIS format and tool takes.
  std::vector<std::string> args = {"-nln", layer.name, "-nlt", geometry_name(layer.geometry), "-lco", "SPATIAL_INDEX=YES"};
  if (!crs.empty()) args.insert(args.end(), {"-a_srs", crs});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALVectorTranslateOptions* options = GDALVectorTranslateOptionsNew(argv.data(), nullptr);
  GDALDatasetH sources[] = {source.get()};
  int usage_error = 0;
  CPLErrorReset();
  GDALDatasetH done = GDALVectorTranslate(nullptr, target, 1, sources, options, &usage_error);
  GDALVectorTranslateOptionsFree(options);
  source.reset();
  VSIUnlink(source_name.c_str());
  if (!done) throw std::runtime_error("GDAL cannot write the " + layer.name + " layer: " + detail::last_gdal_error("no reason given"));
}

}  // namespace

std::string geopackage_bytes(const std::vector<GeoJsonLayer>& layers, const std::string& crs) {
  detail::init_gdal();
  GDALDriverH driver = GDALGetDriverByName("GPKG");
  if (!driver) throw std::runtime_error("this GDAL has no GeoPackage driver");
  const std::string name = detail::memory_file_name(".gpkg");
  {
    detail::Dataset target(GDALCreate(driver, name.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!target) throw std::runtime_error("GDAL cannot create a GeoPackage: " + detail::last_gdal_error("no reason given"));
    try {
      for (const GeoJsonLayer& layer : layers) append_layer(target.get(), layer, crs);
    } catch (...) {
      target.reset();
      VSIUnlink(name.c_str());
      throw;
    }
  }  // closed: the file is complete
  return detail::take_memory_file(name);
}

}  // namespace covmap::gis
