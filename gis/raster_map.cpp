// A best-server raster as a coverage map: the band's values traced into pixel staircases
// (gis/pixel_regions.h), each value's polygons named by its sensor, written as GeoJSON text and
// checked by covmap's GeoJSON reader like every other input (one validator, one set of messages).
#include <ogr_srs_api.h>

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include "gis/map_readers.h"
#include "gis/pixel_regions.h"
#include "gis/raster_table.h"
#include "io/input_error.h"

namespace covmap::gis::detail {
namespace {

// Rasters larger than this are refused before their values are read: 8 bytes a pixel for the
// values and about 9 more for tracing make 2.5e8 pixels about 4 GiB, and a best-server map finer
// than 16000 × 16000 pixels says nothing a coarser one would not (resample it: gdalwarp -tr).
constexpr std::int64_t kMaxRasterPixels = 250'000'000;

struct Georeference {
  double x0 = 0, dx = 1, y0 = 0, dy = 1;  // corner (c, r) is at (x0 + c dx, y0 + r dy)
};

Georeference georeference(GDALDatasetH ds, const std::string& label) {
  double gt[6];
  if (GDALGetGeoTransform(ds, gt) != CE_None)
    throw io::InputError(label, 0, "",
                         "the raster has no georeferencing (no geotransform); add it (gdal_translate -a_ullr … -a_srs …)");
  if (gt[2] != 0.0 || gt[4] != 0.0)
    throw io::InputError(label, 0, "",
                         "the raster's pixels are rotated or sheared; warp it to a north-up grid first (gdalwarp)");
  return {gt[0], gt[1], gt[3], gt[5]};
}

PixelGrid read_band(GDALDatasetH ds, const std::string& label, int band_index) {
  const int bands = GDALGetRasterCount(ds);
  if (band_index < 1 || band_index > bands)
    throw io::InputError(label, 0, "",
                         "no band " + std::to_string(band_index) + "; the raster has " + std::to_string(bands) + " band(s)");
  GDALRasterBandH band = GDALGetRasterBand(ds, band_index);
  const GDALDataType type = GDALGetRasterDataType(band);
  if (!GDALDataTypeIsInteger(type) || GDALDataTypeIsComplex(type))
    throw io::InputError(label, 0, "",
                         "band " + std::to_string(band_index) + " holds " + GDALGetDataTypeName(type) +
                             " values; a best-server raster holds integers (the serving sensor of each pixel): "
                             "convert it, e.g. gdal_translate -ot Int32");
  PixelGrid grid;
  grid.width = GDALGetRasterXSize(ds);
  grid.height = GDALGetRasterYSize(ds);
  const std::int64_t pixels = std::int64_t{grid.width} * grid.height;
  if (pixels > kMaxRasterPixels)
    throw io::InputError(label, 0, "",
                         std::to_string(grid.width) + " × " + std::to_string(grid.height) + " pixels; covmap reads at most " +
                             std::to_string(kMaxRasterPixels) + " (docs/RELIABILITY.md): resample it (gdalwarp -tr) or cut it");
  grid.values.resize(static_cast<std::size_t>(pixels));
  if (GDALRasterIO(band, GF_Read, 0, 0, grid.width, grid.height, grid.values.data(), grid.width, grid.height,
                   GDT_Int64, 0, 0) != CE_None)
    throw io::InputError(label, 0, "", "GDAL could not read band " + std::to_string(band_index) + ": " +
                                           last_gdal_error("no reason given"));
  int has_nodata = 0;
  if (type == GDT_Int64 || type == GDT_UInt64) {
    const std::int64_t nodata = GDALGetRasterNoDataValueAsInt64(band, &has_nodata);
    if (has_nodata) grid.nodata = nodata;
  } else {
    const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
    if (has_nodata && std::isfinite(nodata) && nodata == std::floor(nodata)) grid.nodata = static_cast<std::int64_t>(nodata);
  }
  return grid;
}

// Shortest text that reads back to the same double.
void write_number(std::ostream& out, double v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.write(buffer, end - buffer);
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
      continue;
    }
    out += c;
  }
  return out + "\"";
}

// Where corners go: the georeference, then (geographic data in another datum) to WGS84 lon/lat.
class CornerPlacer {
 public:
  CornerPlacer(Georeference g, OGRCoordinateTransformationH to_wgs84) : g_(g), to_wgs84_(to_wgs84) {}
  Point operator()(PixelCorner c) const {
    double x = g_.x0 + static_cast<double>(c.col) * g_.dx, y = g_.y0 + static_cast<double>(c.row) * g_.dy;
    if (to_wgs84_) OCTTransform(to_wgs84_, 1, &x, &y, nullptr);
    return {x, y};
  }

 private:
  Georeference g_;
  OGRCoordinateTransformationH to_wgs84_;
};

void write_ring(std::ostream& out, const PixelRing& ring, const CornerPlacer& place) {
  out << '[';
  for (std::size_t i = 0; i <= ring.size(); ++i) {  // closed: the first corner again at the end
    const Point p = place(ring[i % ring.size()]);
    out << (i ? ",[" : "[");
    write_number(out, p.x);
    out << ',';
    write_number(out, p.y);
    out << ']';
  }
  out << ']';
}

void write_feature(std::ostream& out, const PixelRegions& regions, const RasterSensor& sensor, const CornerPlacer& place) {
  out << "{\"type\":\"Feature\",\"properties\":{\"sensor\":" << json_string(sensor.id);
  if (!sensor.name.empty()) out << ",\"name\":" << json_string(sensor.name);
  out << ",\"raster_value\":" << regions.value << "},\"geometry\":{\"type\":\"MultiPolygon\",\"coordinates\":[";
  for (std::size_t k = 0; k < regions.polygons.size(); ++k) {
    out << (k ? ",[" : "[");
    write_ring(out, regions.polygons[k].outer, place);
    for (const PixelRing& hole : regions.polygons[k].holes) {
      out << ',';
      write_ring(out, hole, place);
    }
    out << ']';
  }
  out << "]}}";
}

struct TransformCloser {
  void operator()(OGRCoordinateTransformationH t) const {
    if (t) OCTDestroyCoordinateTransformation(t);
  }
};
using Transform = std::unique_ptr<std::remove_pointer_t<OGRCoordinateTransformationH>, TransformCloser>;

// Geographic rasters: their corners to WGS84 lon/lat, whatever the datum and axis order.
Transform to_wgs84(OGRSpatialReferenceH srs, const std::string& label) {
  OGRSpatialReferenceH wgs84 = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(wgs84, 4326);
  OSRSetAxisMappingStrategy(wgs84, OAMS_TRADITIONAL_GIS_ORDER);
  Transform t(OCTNewCoordinateTransformation(srs, wgs84));
  OSRDestroySpatialReference(wgs84);
  if (!t) throw io::InputError(label, 0, "", "GDAL has no transformation from the raster's CRS to WGS84");
  return t;
}

}  // namespace

io::CoverageMap read_raster_map(GDALDatasetH ds, const std::string& label, const MapReadOptions& options,
                                MapSource& source) {
  OGRSpatialReferenceH srs = GDALGetSpatialRef(ds);
  const DataCrs crs = data_crs(srs, label, options.map.planar);
  const Georeference g = georeference(ds, label);
  const PixelGrid grid = read_band(ds, label, options.band);
  const RasterSensors sensors = raster_sensors(ds, options, label);
  const std::vector<PixelRegions> regions = trace_pixel_regions(grid);
  if (regions.empty()) throw io::InputError(label, 0, "", "every pixel is nodata: the raster covers nothing");
  check_every_value_named(regions, sensors, label);
  const Transform transform = crs.kind == DataCrs::Kind::kGeographic ? to_wgs84(srs, label) : nullptr;
  const CornerPlacer place(g, transform.get());
  std::ostringstream text;
  text << "{\"type\":\"FeatureCollection\",\"features\":[";
  for (std::size_t i = 0; i < regions.size(); ++i) {
    if (i) text << ',';
    write_feature(text, regions[i], sensors.of(regions[i].value), place);
  }
  text << "]}";
  io::CoverageMapOptions map_options = options.map;
  map_options.sensor_property = "sensor";
  map_options.crs_frame = crs.frame;
  if (crs.kind == DataCrs::Kind::kGeographic) map_options.declared_geographic_crs = crs.name;
  source.reader = driver_name(ds) + " raster band " + std::to_string(options.band) + " (" + std::to_string(grid.width) +
                  " × " + std::to_string(grid.height) + " pixels" + (sensors.table.empty() ? "" : ", sensors from " + sensors.table) + ")";
  return io::parse_coverage_map(text.str(), label, map_options);
}

}  // namespace covmap::gis::detail
