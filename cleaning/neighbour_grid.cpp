#include "cleaning/neighbour_grid.h"

#include <algorithm>
#include <stdexcept>

#include "core/parallel.h"

namespace covmap::cleaning {

UniformGrid::UniformGrid(double cell, Index index) : cell_(cell), index_kind_(index) {
  if (!(cell > 0.0) || !std::isfinite(cell)) throw std::invalid_argument("UniformGrid: cell size must be positive");
  for (int level = 0; level < kLevels; ++level) level_cell_[level] = level == 0 ? cell : level_cell_[level - 1] * kLevelRatio;
}

void UniformGrid::add_point(int item, Point p) { entries_.emplace_back(key(0, index(p.x, 0), index(p.y, 0)), item); }

void UniformGrid::add_segment(int item, Point a, Point b) { segment_entries(level_cell_, item, a, b, entries_, levels_used_); }

void UniformGrid::Batch::add_segment(int item, Point a, Point b) {
  segment_entries(level_cell_, item, a, b, entries_, levels_used_);
}

void UniformGrid::append(std::vector<Batch>&& batches) {
  std::size_t total = entries_.size();
  for (const Batch& batch : batches) total += batch.entries_.size();
  if (entries_.empty() && !batches.empty() && batches.front().entries_.capacity() >= total) {
    entries_.swap(batches.front().entries_);  // one batch: its entries as they are
  }
  entries_.reserve(total);
  for (Batch& batch : batches) {
    levels_used_ |= batch.levels_used_;
    entries_.insert(entries_.end(), batch.entries_.begin(), batch.entries_.end());
    batch.entries_ = {};  // released as soon as copied
  }
}

void UniformGrid::segment_entries(const double* level_cell, int item, Point a, Point b,
                                  std::vector<std::pair<std::uint64_t, int>>& entries, std::uint32_t& levels_used) {
  // Pieces no longer than a cell: each piece's bounding box spans at most 2×2 cells and contains
  // every cell the piece passes through, so their union covers the segment's cells.
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  int level = 0;
  while (level + 1 < kLevels && !(length <= kMaxCellsPerSegment * level_cell[level])) ++level;
  levels_used |= 1u << level;
  if (level == kLevels - 1) {  // longer than any finite map: one cell that every query visits
    entries.emplace_back(key(level, 0, 0), item);
    return;
  }
  const double cell = level_cell[level];
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::min(length / cell, kMaxCellsPerSegment))));
  const std::size_t first = entries.size();
  for (int k = 0; k < pieces; ++k) {
    const double t0 = static_cast<double>(k) / pieces, t1 = static_cast<double>(k + 1) / pieces;
    const double x0 = a.x + (b.x - a.x) * t0, y0 = a.y + (b.y - a.y) * t0;
    const double x1 = a.x + (b.x - a.x) * t1, y1 = a.y + (b.y - a.y) * t1;
    for (std::int64_t iy = index(std::min(y0, y1), level_cell, level); iy <= index(std::max(y0, y1), level_cell, level); ++iy)
      for (std::int64_t ix = index(std::min(x0, x1), level_cell, level); ix <= index(std::max(x0, x1), level_cell, level); ++ix)
        entries.emplace_back(key(level, ix, iy), item);
  }
  // Consecutive pieces share cells: keep each cell once for this segment.
  std::sort(entries.begin() + static_cast<std::ptrdiff_t>(first), entries.end());
  entries.erase(std::unique(entries.begin() + static_cast<std::ptrdiff_t>(first), entries.end()), entries.end());
}

void UniformGrid::finish(int threads) {
  // Stable: within a cell, items keep insertion order (which is deterministic).
  parallel_stable_sort(entries_.begin(), entries_.end(), threads,
                       [](const auto& l, const auto& r) { return l.first < r.first; });
  std::size_t cells = 0;
  for (std::size_t k = 0; k < entries_.size(); ++k) cells += k == 0 || entries_[k].first != entries_[k - 1].first;
  std::size_t capacity = 16;
  while (capacity < 2 * cells) capacity *= 2;  // load factor at most 1/2
  slots_.assign(capacity, kEmpty);
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    if (k > 0 && entries_[k].first == entries_[k - 1].first) continue;
    std::size_t slot = mix(entries_[k].first) & (capacity - 1);
    while (slots_[slot] != kEmpty) slot = (slot + 1) & (capacity - 1);
    slots_[slot] = static_cast<std::uint32_t>(k);
  }
  build_dense_tables();
}

void UniformGrid::build_dense_tables() {
  if (index_kind_ == Index::kHashOnly) return;
  // Each level's entries are one run of the sorted entries (the level is the key's top byte).
  for (std::size_t begin = 0, end = 0; begin < entries_.size(); begin = end) {
    const std::uint64_t level = key_level(entries_[begin].first);
    std::uint64_t x_lo = kAxisMask, x_hi = 0, y_lo = kAxisMask, y_hi = 0;
    for (end = begin; end < entries_.size() && key_level(entries_[end].first) == level; ++end) {
      const std::uint64_t x = key_x(entries_[end].first), y = key_y(entries_[end].first);
      x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x), y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
    }
    const std::uint64_t nx = x_hi - x_lo + 1, ny = y_hi - y_lo + 1;  // each at most 2^28: no overflow
    if (nx * ny > std::max<std::uint64_t>(kDenseCellsPerEntry * (end - begin), kDenseCellsAlways)) continue;
    DenseTable& t = dense_[level];
    t.x0 = x_lo, t.y0 = y_lo, t.nx = nx, t.ny = ny;
    t.first.resize(nx * ny + 1);
    // Entries are sorted row by row, so their cells' positions in the table never decrease.
    std::size_t e = begin;
    for (std::uint64_t c = 0; c <= nx * ny; ++c) {
      while (e < end) {
        const std::uint64_t x = key_x(entries_[e].first), y = key_y(entries_[e].first);
        if ((y - y_lo) * nx + (x - x_lo) >= c) break;
        ++e;
      }
      t.first[c] = static_cast<std::uint32_t>(e);
    }
  }
}

std::size_t UniformGrid::find(std::uint64_t k) const {
  if (slots_.empty()) return entries_.size();
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t slot = mix(k) & mask; slots_[slot] != kEmpty; slot = (slot + 1) & mask)
    if (entries_[slots_[slot]].first == k) return slots_[slot];
  return entries_.size();
}

}  // namespace covmap::cleaning
