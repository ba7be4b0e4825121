// covmap::mapgen raster polygons: the cells of a labelled raster as polygons with holes.
//
// Contract
//  - Input: a row-major label raster (nx × ny, nx, ny >= 1), labels >= 0 or kNone (no cell).
//  - Output: one GridPolygon per 4-connected component of equal labels (bins that only touch at a
//    corner are different components), in the order of each component's first bin in row-major
//    scan order. Rings follow bin edges and are given in grid-corner coordinates (corner (i, j) is
//    the south-west corner of bin (i, j)); they are closed (first vertex == last), the outer ring
//    runs counter-clockwise, holes clockwise, so the cell is always on the left. Every ring is
//    simple (no vertex visited twice, no edges crossing); rings of one polygon may touch at single
//    corners, where two diagonal bins of the component meet (OGC-valid polygons). Area of the
//    outer ring minus its holes = the component's bin count.
//  - simplify_collinear: vertices inside straight runs are dropped, so only the corners of the
//    staircase remain (as radio-planning tools export); otherwise every bin corner on the boundary
//    is a vertex.
//  - Throws std::invalid_argument when labels.size() != nx·ny.
#pragma once

#include <cstddef>
#include <vector>

namespace covmap::mapgen {

struct GridVertex {
  int i = 0;
  int j = 0;
  friend bool operator==(const GridVertex&, const GridVertex&) = default;
};

using GridRing = std::vector<GridVertex>;  // closed: front() == back()

struct GridPolygon {
  int label = 0;
  std::size_t bins = 0;        // bins in the component
  std::vector<GridRing> rings;  // rings[0]: outer (counter-clockwise); then holes (clockwise)
};

std::vector<GridPolygon> raster_polygons(const std::vector<int>& labels, int nx, int ny, bool simplify_collinear);

// Twice the signed area of a closed ring (positive when counter-clockwise), exact in integers.
long long twice_signed_area(const GridRing& ring);

}  // namespace covmap::mapgen
