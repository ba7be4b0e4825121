// A uniform grid of points and segments for the neighbour queries of map cleaning: "which items
// come within one cell of p". Internal to map_cleaning.
//
// Contract: cell > 0 and finite. Items are added, then finish() is called once, then queries run.
// for_each_near(p, f) calls f(item) for every item that has a point within distance `cell` of p
// (and possibly for some farther ones, and possibly more than once: callers compute the exact
// distance themselves); for_each_within_half_cell likewise for distance cell / 2.
// Deterministic: item order within a cell is insertion order.
//
// Bounded on any input: a segment longer than kMaxCellsPerSegment cells goes to a coarser level
// whose cells are 8^L times larger, the first level at which it spans at most that many cells, so
// adding one costs O(kMaxCellsPerSegment) whatever its length (a mistyped coordinate 10^9 cells
// away once made a single edge register in 10^9 cells). A query visits 3×3 cells (2×2 for the
// half-cell query) on the finest level and 3×3 on each coarser level in use; a coarse cell holds
// only long segments, so realistic maps, whose edges are short, never use one. Cell indices wrap
// modulo 2^28 per axis: far-apart cells may share a key, which only adds candidates. Segments
// too long even for the coarsest level share one cell that every query visits.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/diagram.h"

namespace covmap::cleaning {

class UniformGrid {
 public:
  explicit UniformGrid(double cell);

  void add_point(int item, Point p);
  // Registered in every cell the segment passes through.
  void add_segment(int item, Point a, Point b);
  void finish();

  template <class F>
  void for_each_near(Point p, F&& f) const {
    visit(0, index(p.x, 0) - 1, index(p.y, 0) - 1, 3, f);
    visit_coarse(p, f);
  }
  // The same for items within `radius` <= cell / 2 of p: only the 2×2 cells the disk can reach.
  template <class F>
  void for_each_within_half_cell(Point p, F&& f) const {
    const double fx = p.x / cell_, fy = p.y / cell_;
    const std::int64_t ix = index(p.x, 0), iy = index(p.y, 0);
    visit(0, fx - static_cast<double>(ix) < 0.5 ? ix - 1 : ix, fy - static_cast<double>(iy) < 0.5 ? iy - 1 : iy, 2, f);
    visit_coarse(p, f);
  }

  double cell() const { return cell_; }

  static constexpr double kMaxCellsPerSegment = 32;
  static constexpr double kLevelRatio = 8;  // cell size ratio of consecutive levels
  static constexpr int kLevels = 20;        // 8^19 cells of the finest level: beyond any extent

 private:
  template <class F>
  void visit_coarse(Point p, F& f) const {
    for (int level = 1; level + 1 < kLevels; ++level)
      if (levels_used_ & (1u << level)) visit(level, index(p.x, level) - 1, index(p.y, level) - 1, 3, f);
    if (levels_used_ & (1u << (kLevels - 1))) visit(kLevels - 1, 0, 0, 1, f);
  }
  template <class F>
  void visit(int level, std::int64_t x0, std::int64_t y0, std::int64_t n, F& f) const {
    for (std::int64_t dy = 0; dy < n; ++dy)
      for (std::int64_t dx = 0; dx < n; ++dx) {
        const std::uint64_t k = key(level, x0 + dx, y0 + dy);
        for (std::size_t e = find(k); e < entries_.size() && entries_[e].first == k; ++e) f(entries_[e].second);
      }
  }
  // The first entry of the cell with key k, or entries_.size().
  std::size_t find(std::uint64_t k) const;
  static std::uint64_t mix(std::uint64_t x) {  // splitmix64's finalizer
    x ^= x >> 30;
    x *= 0xBF58476D1CE4E5B9ULL;
    x ^= x >> 27;
    x *= 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
  }
  // Clamped before the conversion, which is undefined beyond the range of int64.
  std::int64_t index(double v, int level) const {
    const double i = std::floor(v / level_cell_[level]);
    return static_cast<std::int64_t>(std::clamp(i, -4e18, 4e18));
  }
  static std::uint64_t key(int level, std::int64_t ix, std::int64_t iy) {
    constexpr std::uint64_t kMask = (std::uint64_t{1} << 28) - 1;
    return (static_cast<std::uint64_t>(level) << 56) | ((static_cast<std::uint64_t>(ix) & kMask) << 28) |
           (static_cast<std::uint64_t>(iy) & kMask);
  }

  double cell_;
  double level_cell_[kLevels];
  std::uint32_t levels_used_ = 1;
  std::vector<std::pair<std::uint64_t, int>> entries_;  // (cell key, item), sorted by finish()
  // Open addressing over the occupied cells: each slot holds the index of a cell's first entry
  // (kEmpty when free); the key is read back from entries_, so a slot costs 4 bytes.
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  std::vector<std::uint32_t> slots_;
};

}  // namespace covmap::cleaning
