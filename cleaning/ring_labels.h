// Which cell lies across each stretch of a coverage map's boundaries. Internal to map_cleaning.
//
// Every ring is sampled (midpoints of pieces of its edges, map_cleaning_tolerances.h); a sample of
// sensor a's ring faces sensor b when an edge of b's rings lies within the snap distance s and runs
// the other way (the same boundary, traced by b with b on its left). The nearest such edge wins.
// No such edge: the frame (kOutside); one of a's own other rings: a seam between pieces of one
// region (kSelf), which is no boundary. Contact says whether the two copies touch, leave a gap (no
// cell between them) or overlap (a's copy lies inside b).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cleaning/neighbour_grid.h"
#include "cleaning/rings.h"

namespace covmap::cleaning {

inline constexpr int kOutside = -1;  // nothing across: the map's frame
inline constexpr int kSelf = -2;     // another piece of the same sensor across

enum class Contact : unsigned char { kTouching, kGap, kOverlap };

struct Across {
  int label = kOutside;
  Point q;  // nearest point of the copy across (when label is a sensor or kSelf)
  Contact contact = Contact::kTouching;
};

struct Sample {
  Point p;
  double s = 0.0;          // arc length along its ring
  int label = kOutside;
  std::uint32_t edge = 0;  // the ring edge it lies on
};

class BoundaryIndex {
 public:
  // threads: for indexing the rings' edges (the index is the same whatever the count).
  BoundaryIndex(const std::vector<BoundaryRing>& rings, double snap, int threads = 1);

  // The cell across ring `ring` at arc length s.
  Across across(int ring, double s) const;
  // The same, at a point p of edge `edge` of ring `ring`, restricted to sensor `sensor` (any
  // sensor when kNone) and to edges within `radius` (at most kRelabelRadius · snap). label is
  // kOutside when none qualifies.
  Across across_at(int ring, std::size_t edge, Point p, int sensor, double radius) const;

  const std::vector<BoundaryRing>& rings() const { return rings_; }
  double snap() const { return snap_; }

 private:
  // An edge as the queries read it, computed once from its ring (start, unit direction, length,
  // the ring's sensor): one record per candidate instead of a walk through ring, points and arc
  // lengths for every edge the grid reports.
  struct Edge {
    Point a;
    Point u;
    double length = 0.0;
    int sensor = kNone;
  };
  const std::vector<BoundaryRing>& rings_;
  double snap_;
  std::vector<std::size_t> first_edge_;  // per ring: its first global edge id
  std::vector<Edge> edges_;              // per global edge id
  UniformGrid grid_;
};

// The samples of one ring, labelled, in arc-length order.
std::vector<Sample> sample_ring(const BoundaryIndex& index, int ring);

// Arc length where ring `ring`'s label changes between s0 (label `label0`) and s1 > s0 (another
// label), located by bisection.
double locate_transition(const BoundaryIndex& index, int ring, double s0, double s1, int label0);

}  // namespace covmap::cleaning
