// A uniform grid that answers "which arcs pass within `reach` of this point" inside a box.
//
// Each arc is clipped to the box, cut into chunks no longer than half a cell, and every chunk's
// bounding box, padded by its sagitta (circle chunks bulge off their chord) and by the arc's reach,
// is entered in the cells it overlaps. A point then only needs the arcs listed in its own cell.
// Clipping first matters: a bisector circle can have a radius 1e7 times the site spacing.
#pragma once

#include <optional>
#include <vector>

#include "check/arc_geometry.h"

namespace covmap::check::detail {

class ArcLocator {
 public:
  // paths[a] unset: arc a is left out. reach[a]: how far from arc a a point may be and still be
  // listed for it (each arc its own: the rounding of a huge circle's numbers is its own).
  ArcLocator(const std::vector<std::optional<ArcPath>>& paths, const Box& box,
             const std::vector<double>& reach);

  // Arcs that may pass within reach of p (a superset); empty outside the box.
  std::vector<int> candidates(Point p) const;

 private:
  Box box_;
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<int> cell_start_;  // CSR: arcs of cell k are arcs_[cell_start_[k] .. [k+1])
  std::vector<int> arcs_;
};

}  // namespace covmap::check::detail
