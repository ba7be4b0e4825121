// A vector coverage map through GDAL/OGR: the chosen layer converted to GeoJSON in memory by GDAL's
// own ogr2ogr (GDALVectorTranslate), then checked by covmap's GeoJSON reader, so that every format
// meets the same checks and messages. Converting rather than walking OGR features here keeps one
// validator: the rules of io/coverage_map.h are not written twice.
#include <gdal_utils.h>
#include <ogr_api.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gis/map_readers.h"
#include "io/input_error.h"

namespace covmap::gis::detail {
namespace {

std::string io_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

std::string layer_list(GDALDatasetH ds) {
  std::string out;
  for (int i = 0; i < GDALDatasetGetLayerCount(ds); ++i)
    out += std::string(i ? ", " : "") + "'" + OGR_L_GetName(GDALDatasetGetLayer(ds, i)) + "'";
  return out;
}

OGRLayerH chosen_layer(GDALDatasetH ds, const std::string& label, const std::string& wanted) {
  const int count = GDALDatasetGetLayerCount(ds);
  if (count == 0) throw io::InputError(label, 0, "", "the file holds no vector layer");
  if (!wanted.empty()) {
    OGRLayerH layer = GDALDatasetGetLayerByName(ds, wanted.c_str());
    if (!layer)
      throw io::InputError(label, 0, "", "no layer '" + wanted + "'; the file's layers: " + layer_list(ds));
    return layer;
  }
  if (count > 1)
    throw io::InputError(label, 0, "",
                         std::to_string(count) + " layers (" + layer_list(ds) + "); name the coverage cells' with --layer");
  return GDALDatasetGetLayer(ds, 0);
}

// GDALVectorTranslate's arguments: one layer to GeoJSON, flat (no Z/M), curves as polylines, and
// lon/lat data in WGS84 (RFC 7946 mode reprojects any geographic CRS) at 1e-12 degrees.
std::vector<std::string> translate_arguments(const std::string& layer, bool geographic) {
  std::vector<std::string> args = {"-f", "GeoJSON", "-dim", "XY", "-nlt", "CONVERT_TO_LINEAR"};
  if (geographic) args.insert(args.end(), {"-lco", "RFC7946=YES", "-lco", "COORDINATE_PRECISION=12"});
  else args.insert(args.end(), {"-lco", "RFC7946=NO", "-lco", "SIGNIFICANT_FIGURES=17"});
  args.push_back(layer);
  return args;
}

}  // namespace

std::string translate_to_geojson(GDALDatasetH ds, const std::string& label, const std::string& layer, bool geographic) {
  std::vector<std::string> args = translate_arguments(layer, geographic);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALVectorTranslateOptions* options = GDALVectorTranslateOptionsNew(argv.data(), nullptr);
  const std::string out = memory_file_name(".geojson");
  GDALDatasetH sources[] = {ds};
  int usage_error = 0;
  CPLErrorReset();
  GDALDatasetH result = GDALVectorTranslate(out.c_str(), nullptr, 1, sources, options, &usage_error);
  GDALVectorTranslateOptionsFree(options);
  if (!result) {
    take_memory_file(out);
    throw io::InputError(label, 0, "", "GDAL could not convert the layer: " + last_gdal_error("no reason given"));
  }
  GDALClose(result);
  return take_memory_file(out);
}

// Data declared geographic whose numbers cannot be degrees: said before GDAL's conversion to WGS84,
// which would wrap or drop them and leave no trace of the real mistake.
void check_degrees(OGRLayerH layer, const DataCrs& crs, const std::string& label) {
  OGREnvelope e;
  if (OGR_L_GetExtent(layer, &e, TRUE) != OGRERR_NONE) return;
  const double largest = std::max({std::abs(e.MinX), std::abs(e.MaxX), std::abs(e.MinY), std::abs(e.MaxY)});
  if (largest <= 360.0) return;
  throw io::InputError(label, 0, "",
                       "the data declare \"" + crs.name +
                           "\", a longitude/latitude CRS, but their coordinates reach " + io_number(largest) +
                           ": not degrees; assign the CRS the coordinates are really in (e.g. ogr2ogr -a_srs EPSG:2056)");
}

io::CoverageMap read_vector_map(GDALDatasetH ds, const std::string& label, const MapReadOptions& options,
                                MapSource& source) {
  OGRLayerH layer = chosen_layer(ds, label, options.layer);
  const std::string layer_name = OGR_L_GetName(layer);
  const DataCrs crs = data_crs(OGR_L_GetSpatialRef(layer), label, options.map.planar);
  if (crs.kind == DataCrs::Kind::kGeographic) check_degrees(layer, crs, label);
  const std::string text = translate_to_geojson(ds, label, layer_name, crs.kind == DataCrs::Kind::kGeographic);
  io::CoverageMapOptions map_options = options.map;
  map_options.crs_frame = crs.frame;
  if (crs.kind == DataCrs::Kind::kGeographic) map_options.declared_geographic_crs = crs.name;
  source.reader = driver_name(ds) + " layer '" + layer_name + "'";
  const std::string where = GDALDatasetGetLayerCount(ds) > 1 ? label + " (layer '" + layer_name + "')" : label;
  return io::parse_coverage_map(text, where, map_options);
}

}  // namespace covmap::gis::detail
