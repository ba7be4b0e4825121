// covmap::io coverage maps: the map a radio planning tool exports, as input to `covmap audit`.
//
// Accepted: a GeoJSON FeatureCollection (RFC 7946) with one Feature per coverage cell. Each
// feature's geometry is a Polygon or MultiPolygon; its properties name the serving sensor under
// options.sensor_property (a non-empty string, or an integer, kept as its decimal text). Several
// features may name the same sensor (a sensor's area may come in pieces); they stay separate
// MapCells. A feature may give the sensor's human name as the string property "name" (null or
// absent: no name), kept in the cell's `name`; with sensor_property "name" the id is the name.
// Names are not checked across features: when the cells of one sensor give different names, the
// map is read all the same and the audit uses the first non-empty one in file order. Positions
// are [lon, lat] in degrees (extra values such as altitude are ignored), or planar [x, y] with
// options.planar, or x/y in a projected CRS: options.crs_frame (the caller knows the CRS), or a
// top-level "crs" that options.resolve_crs turns into a frame (gis/ does both through PROJ). Other
// legacy "crs" members are accepted only as described in io/geojson_crs.h. Unknown members are
// ignored.
//
// Guaranteed on success: at least one cell; every cell has at least one polygon; every ring has at
// least 3 vertices, finite coordinates, no two consecutive vertices equal, no repeated closing
// vertex, non-zero area, and no proper crossing of two of its edges or of an edge of another ring
// of the same polygon; outer rings run counter-clockwise and holes clockwise (input is reversed as
// needed). Lon/lat input is projected with LocalProjection about the centre of the bounding box of
// all vertices (for a map straddling the antimeridian, the centre of the shortest longitude range
// covering it), and max_scale_distortion reports the worst |k/k_centre - 1| over the vertices (see
// io/local_projection.h for why that is the number to watch). Input in a projected CRS is used as
// it is, map.frame is that CRS's frame, and max_scale_distortion is the worst |k/k_centre - 1| on
// a grid over the map's bounding box. Cells keep file order.
//
// Not checked (left to the audit, which can report them as findings rather than refuse the map):
// rings that touch themselves or overlap along an edge without crossing, holes outside their outer
// ring, and overlaps or gaps between different polygons or cells.
//
// Rejected with one InputError listing every problem found, each naming the feature
// ("features[3] (sensor 'a')") and, where useful, the ring and the position index as in the file:
// unreadable file; invalid JSON (byte offset and line; this includes number literals too large for
// a double, the only way a JSON file can hold a non-finite coordinate); a top level that is not a
// FeatureCollection; no features; a feature that is not a Feature or has no Polygon/MultiPolygon
// geometry (other geometry types are named); a missing, empty, or non-string/non-integer sensor
// property (the message lists the properties that do exist); a "name" property that is not a
// string; malformed coordinates; rings not
// closed (RFC 7946: the last position repeats the first); rings with fewer than 3 distinct
// vertices, zero area, or doubling back at their lowest vertex; lon/lat out of range without
// --planar ("coordinates look planar (x=...); use --planar", or, with declared_geographic_crs,
// "assign the CRS the coordinates are really in"); self-crossing rings; mixed crs declarations,
// non-WGS84 ones that cannot be resolved (the resolver's reason, once), and --planar with one that
// can. And what io/input_limits.h bounds (docs/RELIABILITY.md): a file over 1 GiB, JSON nested
// more than 32 levels, more than 10^6 features or 5·10^7 vertices, a planar coordinate beyond
// ±1e8 m; and more distinct sensors than options.max_sensors, refused before the geometry is
// checked. Consecutive repeated positions are dropped silently.
//
// Cost: O(V log V) for V vertices, whatever the shape of the rings (crossings are found by a
// sweep line, io/segment_sweep.h). When a polygon's rings cross at several places, the message
// names one crossing: the first the sweep meets, which depends only on the input. A well-formed
// file is read in one pass over its text, anything else through a JSON document
// (io/coverage_map_drafts.h); a large map's features are checked on the machine's cores
// (io/coverage_map_cells.h). Neither changes a result or a message.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/local_projection.h"
#include "core/coverage_cells.h"
#include "core/diagram.h"

namespace covmap::io {

// The plain map types live in core/coverage_cells.h (the cleaning step reads them).
using MapPolygon = CellPolygon;
using MapCell = CoverageCell;

struct CoverageMap {
  std::vector<MapCell> cells;  // planar metres (projected when geographic)
  // The plane's way back to the earth (io/map_frame.h): covmap's local projection for lon/lat
  // input, the data's projected CRS when one was declared; null for a planar map without a CRS.
  std::shared_ptr<const MapFrame> frame;
  double max_scale_distortion = 0.0;  // worst |k/k0 - 1| over all vertices (0 for planar)
  std::size_t vertex_count = 0;       // vertices kept, over all rings
};

struct CoverageMapOptions {
  // The feature property that names the serving sensor (`covmap audit --sensor-property`).
  std::string sensor_property = "sensor";
  // true: positions are planar [x, y] in metres (or any one unit), used as they are, and any crs
  // declaration is accepted (`--planar`). false: positions are WGS84 [lon, lat].
  bool planar = false;
  // Refuse, before the geometry is checked, a map naming more distinct sensors than this (0: no
  // limit). `covmap audit` passes its own limit (audit::kMaxSensors), so an
  // oversized map is refused after the JSON is parsed instead of after every ring is validated.
  std::size_t max_sensors = 0;
  // The data's projected CRS, when the caller already knows it (gis/ reading a GDAL dataset):
  // positions are then its metres, used as they are, and the file's "crs" members are not judged.
  // Must not be set with `planar`.
  std::shared_ptr<const MapFrame> crs_frame;
  // Turns the name of a non-WGS84 "crs" declaration at the top of the file ("EPSG:2056",
  // "urn:ogc:def:crs:EPSG::2056") into the frame of that CRS (gis/ does it through PROJ; it throws
  // InputError for a CRS covmap cannot use). Empty: such a declaration is refused unless `planar`;
  // set: `planar` with such a declaration is refused instead (the data say what they are).
  CrsResolver resolve_crs;
  // The name of the geographic CRS the data declared, when a caller converted them to WGS84 lon/lat
  // first (gis/ reading a GDAL dataset): messages about coordinates that are not lon/lat then name
  // it instead of suggesting --planar. Empty: GeoJSON's own WGS84.
  std::string declared_geographic_crs;
};

CoverageMap read_coverage_map(const std::filesystem::path& path, const CoverageMapOptions& options = {});

// Parses text already in memory; `file` is only used in error messages.
CoverageMap parse_coverage_map(std::string_view text, const std::string& file, const CoverageMapOptions& options = {});

}  // namespace covmap::io
