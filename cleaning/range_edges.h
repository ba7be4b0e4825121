// Range edges: where a sensor's coverage ends at a reception limit rather than at the map's frame.
// Internal to map_cleaning.
//
// In the path-loss model the coverage of sensor i ends on the circle about it of radius R·w_i. A
// map's outside boundary is either the frame of the area the map was computed over (the raster's
// extent, a study area's polygon) or such a range edge. find_range_edges tells them apart without
// knowing the sensors:
//   - vertices within kFrameBoxReach snaps of a side of the map's bounding box are the raster's
//     own frame; the rest of each frame chain is split there into pieces;
//   - a sensor's pieces are a range edge when one circle fits them all (rms ≤ kRangeEdgeRms snaps)
//     whose centre lies inside the sensor's own region (every site lies in its own cell) and which
//     contains the whole region (within kRangeDiscSlack snaps): a sensor's region is inside its
//     reach. Pieces that do not fit together are tried one by one.
// A straight or gently curved frame (a lon/lat raster's parallels in the plane, a study area's
// border) fits a line or a circle whose centre is far outside the cell, and stays frame.
#pragma once

#include "cleaning/map_cleaning.h"
#include "cleaning/rings.h"

namespace covmap::cleaning {

// Fills map.range_edges from map.chains (frame chains) and the rings of each sensor.
void find_range_edges(CleanedMap& map, const MapRings& rings, double snap, double huber, double line_preference);

}  // namespace covmap::cleaning
