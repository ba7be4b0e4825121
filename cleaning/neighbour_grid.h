// A uniform grid of points and segments for the neighbour queries of map cleaning: "which items
// come within one cell of p". Internal to map_cleaning.
//
// Contract: cell > 0 and finite. Items are added, then finish() is called once, then queries run.
// Segments may also be gathered in Batches (one per thread) and appended in order: the grid is the
// same as if their segments had been added directly in that order.
// for_each_near(p, f) calls f(item) for every item that has a point within distance `cell` of p
// (and possibly for some farther ones, and possibly more than once: callers compute the exact
// distance themselves); for_each_within_half_cell likewise for distance cell / 2.
// Deterministic: item order within a cell is insertion order, and cells are visited row by row
// (y outer, x inner), whichever index below serves them.
//
// Two indexes over the same sorted entries. Cells are found through an open-addressing hash; on a
// level whose occupied cells fill their bounding box densely enough, or whose box is small (the
// coarse levels of a map: its few long edges over a box 8^L times smaller), a dense row-major table
// of first entries serves a query's row of cells as one contiguous run instead of one hash probe
// per cell. The probes' cache misses are a large part of the map cleaning's CPU time otherwise,
// most of them on level 1, which every query visits once a map has an edge over 32 cells long.
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
  enum class Index { kAuto, kHashOnly };  // kHashOnly: never the dense table (tests compare the two)
  explicit UniformGrid(double cell, Index index = Index::kAuto);

  // Segments' entries gathered apart from the grid (on another thread), for append().
  class Batch {
   public:
    explicit Batch(const UniformGrid& grid) : level_cell_(grid.level_cell_) {}
    void add_segment(int item, Point a, Point b);

   private:
    friend class UniformGrid;
    const double* level_cell_;
    std::uint32_t levels_used_ = 0;
    std::vector<std::pair<std::uint64_t, int>> entries_;
  };

  void add_point(int item, Point p);
  // Registered in every cell the segment passes through.
  void add_segment(int item, Point a, Point b);
  // The batches' entries after those added so far, in the batches' order.
  void append(std::vector<Batch>&& batches);
  // threads: for sorting the entries (the result is the same whatever the count).
  void finish(int threads = 1);

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
    for (std::int64_t dy = 0; dy < n; ++dy) {
      std::size_t from = 0, to = 0;
      if (dense_row(level, x0, y0 + dy, n, from, to)) {
        for (std::size_t e = from; e < to; ++e) f(entries_[e].second);
        continue;
      }
      for (std::int64_t dx = 0; dx < n; ++dx) {
        const std::uint64_t k = key(level, x0 + dx, y0 + dy);
        for (std::size_t e = find(k); e < entries_.size() && entries_[e].first == k; ++e) f(entries_[e].second);
      }
    }
  }
  // A level's dense table: per cell of the box [x0, x0 + nx) × [y0, y0 + ny) (wrapped indices),
  // row-major, the index of its first entry, and one more at the end. Empty: the hash serves it.
  struct DenseTable {
    std::uint64_t x0 = 0, y0 = 0, nx = 0, ny = 0;
    std::vector<std::uint32_t> first;
  };
  // The entries of cells x0 … x0 + n − 1 of row y of `level`, as the run [from, to), when its dense
  // table holds them in that order (false: use the hash, also when the row wraps around the keys).
  bool dense_row(int level, std::int64_t x0, std::int64_t y, std::int64_t n, std::size_t& from, std::size_t& to) const {
    const DenseTable& t = dense_[level];
    if (t.first.empty()) return false;
    const std::uint64_t first = wrapped(x0), last = wrapped(x0 + n - 1), row = wrapped(y);
    if (first > last) return false;
    from = to = 0;
    if (row < t.y0 || row >= t.y0 + t.ny) return true;  // no cell of the row is occupied
    const std::uint64_t a = std::max(first, t.x0), b = std::min(last + 1, t.x0 + t.nx);
    if (a >= b) return true;
    const std::uint64_t row_start = (row - t.y0) * t.nx;
    from = t.first[row_start + (a - t.x0)];
    to = t.first[row_start + (b - t.x0)];
    return true;
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
  std::int64_t index(double v, int level) const { return index(v, level_cell_, level); }
  // Modulo 2^28, offset by 2^27 so that the indices around 0 (maps centred on their origin) stay
  // in order: a dense table needs its box unbroken by the wrap.
  static constexpr int kAxisBits = 28;
  static constexpr std::uint64_t kAxisMask = (std::uint64_t{1} << kAxisBits) - 1;
  static std::uint64_t wrapped(std::int64_t i) {
    return (static_cast<std::uint64_t>(i) + (std::uint64_t{1} << (kAxisBits - 1))) & kAxisMask;
  }
  // A key's wrapped column and row, and its level.
  static std::uint64_t key_x(std::uint64_t k) { return k & kAxisMask; }
  static std::uint64_t key_y(std::uint64_t k) { return (k >> kAxisBits) & kAxisMask; }
  static std::uint64_t key_level(std::uint64_t k) { return k >> 56; }
  // Row-major: sorted keys list a level's cells row by row, x increasing within a row.
  static std::uint64_t key(int level, std::int64_t ix, std::int64_t iy) {
    return (static_cast<std::uint64_t>(level) << 56) | (wrapped(iy) << kAxisBits) | wrapped(ix);
  }

  // Appends the entries of segment a–b to `entries` and marks its level in `levels_used`.
  static void segment_entries(const double* level_cell, int item, Point a, Point b,
                              std::vector<std::pair<std::uint64_t, int>>& entries, std::uint32_t& levels_used);
  static std::int64_t index(double v, const double* level_cell, int level) {
    const double i = std::floor(v / level_cell[level]);
    return static_cast<std::int64_t>(std::clamp(i, -4e18, 4e18));
  }

  double cell_;
  double level_cell_[kLevels];
  std::uint32_t levels_used_ = 1;
  std::vector<std::pair<std::uint64_t, int>> entries_;  // (cell key, item), sorted by finish()
  // Open addressing over the occupied cells: each slot holds the index of a cell's first entry
  // (kEmpty when free); the key is read back from entries_, so a slot costs 4 bytes.
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  std::vector<std::uint32_t> slots_;
  Index index_kind_;
  DenseTable dense_[kLevels];
  // A level gets a dense table when its box has at most this many cells per entry, or at most
  // kDenseCellsAlways cells (4 MiB).
  static constexpr std::uint64_t kDenseCellsPerEntry = 4;
  static constexpr std::uint64_t kDenseCellsAlways = std::uint64_t{1} << 20;
  void build_dense_tables();
};

}  // namespace covmap::cleaning
