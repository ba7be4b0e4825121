#include "gis/sensor_reader.h"

#include <algorithm>
#include <stdexcept>

#include "gis/crs_frame.h"
#include "gis/map_readers.h"
#include "io/input_error.h"

namespace covmap::gis {
namespace {

// Files covmap reads itself: CSV in any common delimiter, sites JSON, GeoJSON.
bool covmap_reads_itself(const std::filesystem::path& path) {
  const std::string ext = detail::ascii_lower(path.extension().string());
  return ext == ".csv" || ext == ".tsv" || ext == ".txt" || ext == ".json" || ext == ".geojson" || ext.empty();
}

std::shared_ptr<const io::MapFrame> named_crs(const std::string& definition, const std::string& label) {
  if (definition.empty()) return nullptr;
  try {
    return projected_crs_frame(definition);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(label, 0, "--sensor-crs", e.what());
  }
}

// A GDAL layer of points: converted to GeoJSON in memory and read by covmap's GeoJSON reader, in
// WGS84 lon/lat for a geographic CRS, as x/y in the layer's projected CRS, or as x/y in
// --sensor-crs (or the map's plane, for a planar map) for a layer without one.
std::vector<ReportedSensor> read_layer(const std::filesystem::path& path, const SensorReadOptions& options) {
  const std::string label = path.string();
  const detail::Dataset ds = detail::open_dataset(label, GDAL_OF_VECTOR);
  if (!ds || GDALDatasetGetLayerCount(ds.get()) == 0)
    throw io::InputError(label, 0, "",
                         "neither covmap nor GDAL reads this file as sensors (" + detail::last_gdal_error("no driver took it") +
                             "); give CSV, covmap.sites/1 JSON, GeoJSON Points or a GDAL vector layer of Points");
  OGRLayerH layer = GDALDatasetGetLayerCount(ds.get()) == 1 && options.layer.empty()
                        ? GDALDatasetGetLayer(ds.get(), 0)
                        : GDALDatasetGetLayerByName(ds.get(), options.layer.c_str());
  if (!layer)
    throw io::InputError(label, 0, "",
                         options.layer.empty() ? "several layers; name the sensors' with --sensor-layer"
                                               : "no layer '" + options.layer + "'");
  io::ReportedSensorOptions so = options.sensors;
  OGRSpatialReferenceH srs = OGR_L_GetSpatialRef(layer);
  bool geographic = false;
  if (srs) {
    geographic = OSRIsGeographic(srs);
    if (!geographic) so.xy_frame = detail::data_crs(srs, label, false).frame;
    so.planar = false;
  } else if (!options.sensor_crs.empty()) {
    so.xy_frame = named_crs(options.sensor_crs, label);
  } else if (!so.planar) {
    throw io::InputError(label, 0, "",
                         "the sensor layer declares no coordinate reference system; name it with --sensor-crs "
                         "(e.g. EPSG:2056), or assign it (ogr2ogr -a_srs)");
  }
  if (so.frame == nullptr && (geographic || so.xy_frame))
    throw io::InputError(label, 0, "",
                         "the sensors are in a coordinate reference system but the map has none (--planar); give "
                         "them in the map's own x/y without a CRS");
  const std::string text = detail::translate_to_geojson(ds.get(), label, OGR_L_GetName(layer), geographic);
  return io::parse_reported_sensors(text, label, so, io::SensorsFormat::kGeoJson);
}

}  // namespace

std::vector<ReportedSensor> read_any_sensors(const std::filesystem::path& path, const SensorReadOptions& options) {
  if (!covmap_reads_itself(path)) return read_layer(path, options);
  io::ReportedSensorOptions so = options.sensors;
  so.xy_frame = named_crs(options.sensor_crs, path.string());
  so.resolve_crs = proj_crs_resolver();
  return io::read_reported_sensors(path, so);
}

}  // namespace covmap::gis
