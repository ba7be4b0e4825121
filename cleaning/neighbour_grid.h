// A uniform grid of points and segments for the neighbour queries of map cleaning: "which items
// come within one cell of p". Internal to map_cleaning.
//
// Contract: cell > 0 and finite. Items are added, then finish() is called once, then queries run.
// for_each_near(p, f) calls f(item) for every item that has a point within distance `cell` of p
// (and possibly for some farther ones, and possibly more than once: callers compute the exact
// distance themselves); for_each_within_half_cell likewise for distance cell / 2. Cost:
// O(1 + length / cell) per added segment; a query visits 3×3 (2×2) cells.
// Deterministic: item order within a cell is insertion order.
#pragma once

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
    visit(index(p.x) - 1, index(p.y) - 1, 3, f);
  }
  // The same for items within `radius` <= cell / 2 of p: only the 2×2 cells the disk can reach.
  template <class F>
  void for_each_within_half_cell(Point p, F&& f) const {
    const double fx = p.x / cell_, fy = p.y / cell_;
    const std::int64_t ix = static_cast<std::int64_t>(std::floor(fx)), iy = static_cast<std::int64_t>(std::floor(fy));
    visit(fx - static_cast<double>(ix) < 0.5 ? ix - 1 : ix, fy - static_cast<double>(iy) < 0.5 ? iy - 1 : iy, 2, f);
  }

  double cell() const { return cell_; }

 private:
  template <class F>
  void visit(std::int64_t x0, std::int64_t y0, std::int64_t n, F& f) const {
    for (std::int64_t dy = 0; dy < n; ++dy)
      for (std::int64_t dx = 0; dx < n; ++dx) {
        const std::uint64_t k = key(x0 + dx, y0 + dy);
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
  std::int64_t index(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  static std::uint64_t key(std::int64_t ix, std::int64_t iy) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32) |
           static_cast<std::uint32_t>(iy);
  }

  double cell_;
  std::vector<std::pair<std::uint64_t, int>> entries_;  // (cell key, item), sorted by finish()
  // Open addressing over the occupied cells: each slot holds the index of a cell's first entry
  // (kEmpty when free); the key is read back from entries_, so a slot costs 4 bytes.
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  std::vector<std::uint32_t> slots_;
};

}  // namespace covmap::cleaning
