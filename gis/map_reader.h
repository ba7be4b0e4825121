// covmap::gis map reader: a coverage map from any file a planner has — GeoJSON, any vector format
// GDAL reads (GeoPackage, Shapefile, FlatGeobuf, KML, MapInfo, …) or a best-server raster (any
// GDAL raster: GeoTIFF, …) — in lon/lat or in a projected CRS, read into io::CoverageMap.
//
// How each input is read (docs/FORMATS.md lists them with their GDAL drivers):
//  - GeoJSON (.geojson/.json, or text starting with '{'): covmap's own reader (io/coverage_map.h),
//    which names features and positions in its messages. A top-level "crs" naming a projected
//    CRS is used through PROJ (gis/crs_frame.h); none means WGS84 lon/lat (RFC 7946).
//  - Other vector data: GDAL/OGR converts the chosen layer (options.layer, or the only one) to
//    GeoJSON in memory — in WGS84 lon/lat for a geographic CRS, in the layer's own coordinates for
//    a projected one — and covmap's reader checks it, so every input meets the same checks and
//    messages ("features[3]" is the layer's fourth feature).
//  - Rasters: band options.band's integer values name the serving sensor (nodata: no coverage);
//    covmap traces the pixel boundaries itself (gis/pixel_regions.h), so a cell's boundary is its
//    pixel staircase, exactly as the raster has it. The value is the sensor id, or is mapped to
//    one by options.raster_table (CSV: value, sensor[, name]) or by the band's raster attribute
//    table (a value column and a column named options.sensor_property, else the name column).
// The CRS comes from the data: projected CRSs in metres are the plane as they are (io::MapFrame of
// kind kProjectedCrs), geographic ones are projected as lon/lat maps always were. Data without
// any CRS need options.planar; options.planar with data that declare a CRS is refused.
//
// Guaranteed on success: what io/coverage_map.h guarantees of the map it returns (every input
// ends in its reader), whatever the format. map.frame is the data's projected CRS (a PROJ frame)
// when they have one, covmap's local projection for lon/lat data, and null for data without a CRS
// with options.planar. A raster gives one cell per band value present (ascending), its polygons
// the value's 4-connected pixel regions, its sensor (and name) the one the value names. `source`, when
// given, says which reader took the file.
//
// Rejected with io::InputError naming the file (and layer) and what to do: a file no reader
// takes; several layers without options.layer (the message lists them); a missing layer or band;
// a raster band that is not of an integer type, or rotated/sheared pixels; values without a
// sensor in the table; a CRS that is not usable (gis/crs_frame.h); no CRS without --planar; and
// everything io/coverage_map.h rejects.
#pragma once

#include <filesystem>
#include <string>

#include "io/coverage_map.h"

namespace covmap::gis {

struct MapReadOptions {
  // As io::CoverageMapOptions: the property naming the serving sensor, --planar, and the limit on
  // distinct sensors.
  io::CoverageMapOptions map;
  // The vector layer to read (`--layer`); empty: the file's only layer.
  std::string layer;
  // The raster band holding the serving sensor (`--band`), from 1.
  int band = 1;
  // A CSV table from raster values to sensors (`--raster-table`): columns value, sensor[, name].
  std::filesystem::path raster_table;
};

// Which reader a file went through, for people ("GeoJSON (covmap)", "GPKG layer 'cells'",
// "GTiff raster band 1").
struct MapSource {
  std::string reader;
};

io::CoverageMap read_any_coverage_map(const std::filesystem::path& path, const MapReadOptions& options,
                                      MapSource* source = nullptr);

}  // namespace covmap::gis
