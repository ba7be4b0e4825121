// A coverage map as plain planar data: which sensor serves which polygons. io/coverage_map.h reads
// it from GeoJSON (projecting lon/lat); cleaning/map_cleaning.h turns it into an arc graph.
#pragma once

#include <string>
#include <vector>

#include "core/diagram.h"

namespace covmap {

using Ring = std::vector<Point>;  // implicitly closed: last point != first

struct CellPolygon {
  Ring outer;               // counter-clockwise
  std::vector<Ring> holes;  // each clockwise
};

// One cell of the map (one GeoJSON feature): the area one sensor serves, possibly in pieces.
struct CoverageCell {
  std::string sensor;                 // the serving sensor's id
  int feature = 0;                    // index in the input file, for messages
  std::vector<CellPolygon> polygons;
  std::string name;                   // the sensor's human name as the feature gives it; may be empty
};

}  // namespace covmap
