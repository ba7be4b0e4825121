// covmap::voronoi best-server raster: which sensor serves the centre of each square bin.
//
// Contract
//  - Input: sites with finite coordinates and finite positive weights (validated by the caller), a RasterGrid with nx, ny >= 1 and bin > 0, and optionally a
//    maximum weighted range.
//  - Output: for every bin (i, j), label = the index of the site minimizing
//        d(p, s) = std::sqrt(dx * dx + dy * dy) / s.weight,   p = (grid.center_x(i), grid.center_y(j)),
//    computed exactly so in double; ties go to the lowest index. A bin whose smallest d exceeds
//    max_weighted_range gets kNone (not covered). The result equals brute force over all sites bit
//    for bit: pruning only ever discards sites that cannot win (see voronoi/tolerances.h).
//  - Cost: the raster is split recursively into blocks; each block keeps only the sites whose
//    lower bound on d over the block is within the block's upper bound on the best d. Blocks with
//    one candidate are filled without per-bin work when no range is set. About O(bins + n log bins)
//    for well-spread sites: 10^6 bins and 10^4 sites take well under a second.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "core/diagram.h"

namespace covmap::voronoi {

// A raster of nx × ny square bins; bin (i, j) covers [x0 + i·bin, x0 + (i+1)·bin] × [y0 + j·bin, ...].
// Rows run south to north (j = 0 is the southernmost row), columns west to east.
struct RasterGrid {
  double x0 = 0.0;   // west edge, metres
  double y0 = 0.0;   // south edge, metres
  double bin = 1.0;  // side of a bin, metres
  int nx = 0;
  int ny = 0;

  double corner_x(int i) const { return x0 + i * bin; }
  double corner_y(int j) const { return y0 + j * bin; }
  double center_x(int i) const { return x0 + (i + 0.5) * bin; }
  double center_y(int j) const { return y0 + (j + 0.5) * bin; }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + i; }
  std::size_t bins() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
};

struct BestServerRaster {
  RasterGrid grid;
  std::vector<int> labels;  // grid.bins() entries, row-major (index(i, j)); site index or kNone
};

// Throws std::invalid_argument for an empty grid or a non-positive bin.
BestServerRaster best_server_raster(std::span<const Site> sites, const RasterGrid& grid,
                                    std::optional<double> max_weighted_range = std::nullopt);

}  // namespace covmap::voronoi
