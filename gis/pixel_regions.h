// The regions of a best-server raster as staircase polygons along the pixel edges.
// covmap traces the pixel boundaries itself rather than asking GDAL to polygonize: the staircases
// are what map cleaning expects. Pure algorithm: no GDAL, no file I/O, no other covmap library.
//
// Contract.
// Input: a PixelGrid of width × height integer values, row-major with row 0 first, and an optional
// nodata value. Rejected with std::invalid_argument naming the numbers: a negative width or
// height; values.size() != width * height; more than kMaxPixels pixels. An empty grid (width or
// height 0) gives an empty result.
//
// Coordinates: pixel corners, integers. Pixel (c, r) spans corners c..c+1 and r..r+1; col grows to
// the right, row grows downwards (as the raster is drawn on screen).
//
// Output: one PixelRegions per value present in the grid other than nodata, by ascending value.
// - Regions are 4-connected: one PixelPolygon per 4-connected set of equal-valued pixels (a
//   "component"). Two pixels of one value that touch only at a corner are in two polygons unless
//   the component joins them by another path.
// - Polygons of one value are ordered by their first pixel in row-major order.
// - A polygon's `outer` ring bounds its component; each of its `holes` bounds one 4-connected
//   set of other pixels (other values, nodata, or both) enclosed by it. The pixels whose centres
//   lie inside a polygon (even-odd over outer and holes) are exactly its component, so its area
//   (outer minus holes) is its pixel count.
// - Orientation: every ring is walked with its own component on the right. On screen (row down)
//   outer rings run clockwise and holes counter-clockwise; equivalently, the shoelace sum
//   Σ (col_i · row_{i+1} − col_{i+1} · row_i) is positive for outer rings and negative for holes
//   in (col, row) coordinates.
// - Rings are not closed (the first corner is not repeated), hold only real turns (consecutive
//   edges alternate horizontal and vertical; no collinear vertex) and start at their smallest
//   corner by (row, col), i.e. the top-most, then left-most one.
// - Every ring is simple: no corner twice, no crossing. Pinch convention: at a corner where a
//   component holds two diagonally opposite pixels and not the other two, the component's rings
//   pair the four edges around each of the *other* two pixels (the walk turns towards the
//   component). Those two other pixels are then always in different enclosed sets, so the two
//   pairs belong to two different rings of the polygon (outer and hole, or two holes), which
//   touch at that corner only. If the two diagonal pixels are in different components (same value
//   or not), each component's ring turns around its own pixel instead; the rings of both touch
//   at the corner. Rings never share an edge within a polygon.
// - Deterministic: the same grid gives the same output, vertex for vertex.
//
// Cost: O(width · height) time for labelling and tracing, plus sorting the distinct values; memory
// about 5 bytes per pixel beyond the input (a 32-bit component id and a byte of traced-edge flags),
// plus up to 4 bytes per pixel of explicit flood-fill stack. No recursion, no per-pixel heap
// objects; the output holds one small object per component and one vertex per turn.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace covmap::gis {

struct PixelGrid {
  int width = 0;   // columns
  int height = 0;  // rows
  std::vector<std::int64_t> values;    // row-major, row 0 first; size width * height
  std::optional<std::int64_t> nodata;  // pixels with this value belong to no region
};

// A pixel corner: pixel (c, r) spans corners (c..c+1, r..r+1).
struct PixelCorner {
  std::int64_t col = 0;
  std::int64_t row = 0;
  bool operator==(const PixelCorner&) const = default;
};

// Not closed (the first corner is not repeated); corners only (no collinear middle vertices).
using PixelRing = std::vector<PixelCorner>;

struct PixelPolygon {
  PixelRing outer;               // clockwise on screen
  std::vector<PixelRing> holes;  // counter-clockwise on screen
};

struct PixelRegions {
  std::int64_t value = 0;
  std::vector<PixelPolygon> polygons;  // by first pixel in row-major order
};

// Component ids are 32-bit with one value reserved for "no component".
inline constexpr std::int64_t kMaxPixels = 4294967294;  // 2^32 - 2

// Every value but nodata, ascending by value. Throws std::invalid_argument on invalid input.
std::vector<PixelRegions> trace_pixel_regions(const PixelGrid& grid);

}  // namespace covmap::gis
