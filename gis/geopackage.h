// covmap::gis GeoPackage output: GeoJSON layers (the audit's sensors, shifts and diagram) written
// as one GeoPackage (OGC 12-128r18) by GDAL's GPKG driver, in memory, so that the caller writes
// the bytes all-or-nothing (io/atomic_file.h) like every other report.
//
// Contract: each layer's FeatureCollection becomes a table of that name with its properties as
// columns (types as GDAL's GeoJSON reader infers them) and its one geometry type; the coordinates are
// written as given and tagged with `crs` (any definition PROJ reads: "EPSG:4326" for lon/lat, the
// map's WKT for its projected CRS; empty: an undefined Cartesian CRS, for planar maps). Throws
// std::runtime_error with GDAL's reason if GDAL fails; nothing is written to disk here.
#pragma once

#include <string>
#include <vector>

namespace covmap::gis {

// The one geometry type of a table; Polygons are stored as MultiPolygons so that a table can hold
// both (a sensor's region may come in pieces).
enum class LayerGeometry { kPoint, kLineString, kMultiPolygon };

struct GeoJsonLayer {
  std::string name;     // table name: "sensors", "shifts", "diagram"
  LayerGeometry geometry = LayerGeometry::kPoint;
  std::string geojson;  // a FeatureCollection of that geometry (Polygon or MultiPolygon for kMultiPolygon)
};

// The bytes of a GeoPackage file holding every layer.
std::string geopackage_bytes(const std::vector<GeoJsonLayer>& layers, const std::string& crs);

}  // namespace covmap::gis
