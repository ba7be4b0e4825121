// covmap::io clip polygons: the --clip argument, as a rectangle or a polygon file.
//
// Accepted `spec`:
//   "xmin,ymin,xmax,ymax"  four numbers: an axis-aligned rectangle (xmin < xmax, ymin < ymax);
//   a path to a JSON file holding one of
//     {"format":"covmap.polygon/1","points":[[x,y], ...]}
//     a GeoJSON Polygon, a Feature whose geometry is a Polygon, or a FeatureCollection holding
//     exactly one such Feature (the outer ring is used; extra coordinates such as altitude are
//     ignored; a polygon with holes is rejected because clipping would silently ignore them).
// A closing vertex equal to the first, and consecutive repeated vertices, are dropped.
//
// Guaranteed on success: a simple polygon (no self-intersection or touching), at least 3 vertices,
// finite coordinates, non-zero area, in counter-clockwise order (clockwise input is reversed).
// Rejected with InputError naming the file (or the spec) and the JSON path or defect.
#pragma once

#include <string>
#include <vector>

#include "core/diagram.h"

namespace covmap::io {

std::vector<Point> parse_clip(const std::string& spec);

// The polygon part of parse_clip for a document already parsed from JSON text; `file` names it
// in errors.
std::vector<Point> parse_polygon_json(const std::string& text, const std::string& file);

// Normalizes and validates a ring as parse_clip does (drops the closing and repeated vertices,
// checks with polygon_defect, returns it counter-clockwise). Throws InputError(file, 0, item, defect).
std::vector<Point> make_clip_polygon(std::vector<Point> ring, const std::string& file,
                                              const std::string& item);

}  // namespace covmap::io
