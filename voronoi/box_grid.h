// A uniform grid of boxes for "which items may meet this point or box?" queries, filled by all
// workers. Shared by face tracing (hole rays, containment candidates) and the graph comparison
// (points near a graph). Internal to covmap's algorithms; not part of the diagram data.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "voronoi/arc_path.h"
#include "core/parallel.h"
#include "core/large_buffer.h"

namespace covmap::voronoi {


// Boxes in a uniform grid of cells, stored in compressed rows (cell_begin[c] .. cell_begin[c+1]
// index into items). Items with an unbounded or a large box are kept apart in `always`; a query
// tests those and the items of its cells.
struct BoxGrid {
  double x0 = 0, y0 = 0, cw = 1, ch = 1;
  int nx = 0, ny = 0;
  LargeVector<int> cell_begin, items, always;

  // Clamped to the grid before the conversion (far points would overflow an int; NaN -> 0).
  static int clamp_index(double c, int n) { return !(c > 0) ? 0 : c >= n - 1 ? n - 1 : static_cast<int>(c); }
  int column(double x) const { return clamp_index(std::floor((x - x0) / cw), nx); }
  int row(double y) const { return clamp_index(std::floor((y - y0) / ch), ny); }
  std::span<const int> cell(int i, int j) const {
    const std::size_t c = static_cast<std::size_t>(j) * nx + i;
    return {items.data() + cell_begin[c], items.data() + cell_begin[c + 1]};
  }
};

// A grid of about `target` cells over `area` (boxes reaching outside it land in the border cells).
// `box_of(k)` gives the box of item k < n; it is called twice per item (count, then fill), so the
// boxes need no storage of their own. Boxes covering more than `max_cells` cells go to `always`.
template <class BoxOf>
BoxGrid make_grid(std::size_t n, BoxOf&& box_of, Box area, std::size_t target, long long max_cells) {
  BoxGrid g;
  const int side = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(target))), 1, 2048);
  if (!area.finite()) {
    for (std::size_t k = 0; k < n; ++k) g.always.push_back(static_cast<int>(k));
    return g;
  }
  g.nx = g.ny = side;
  g.x0 = area.xmin, g.y0 = area.ymin;
  g.cw = std::max((area.xmax - area.xmin) / side, 1e-300);
  g.ch = std::max((area.ymax - area.ymin) / side, 1e-300);
  const std::size_t cells = static_cast<std::size_t>(side) * side;
  auto for_cells = [&](const Box& b, auto&& f) {
    const int i0 = g.column(b.xmin), i1 = g.column(b.xmax), j0 = g.row(b.ymin), j1 = g.row(b.ymax);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) f(static_cast<std::size_t>(j) * side + i);
  };
  // Boxes that are unbounded or would cover more than max_cells cells (faces reaching far out:
  // the grid spans the central nodes only) are kept in `always`, tested by every query.
  auto gridded = [&](const Box& b) {
    if (!b.finite()) return false;
    const long long cells_covered = static_cast<long long>(g.column(b.xmax) - g.column(b.xmin) + 1) * (g.row(b.ymax) - g.row(b.ymin) + 1);
    return cells_covered <= max_cells;
  };
  // Counted and filled by the workers, each over its own contiguous range of items; within
  // a cell the first range's items come first, so rows are in item order as a sequential fill
  // makes them. `always` is in item order too.
  const int workers = worker_count(n);
  std::vector<LargeVector<int>> count(workers);
  std::vector<std::vector<int>> unbounded(workers);
  parallel_chunks(n, workers, [&](std::size_t b, std::size_t e, int w) {
    count[w].assign(cells, 0);
    for (std::size_t k = b; k < e; ++k) {
      const Box box = box_of(k);
      if (gridded(box)) for_cells(box, [&](std::size_t c) { ++count[w][c]; });
      else if (box.xmin <= box.xmax) unbounded[w].push_back(static_cast<int>(k));
    }
  });
  g.cell_begin.assign(cells + 1, 0);
  for (std::size_t c = 0; c < cells; ++c) {
    int total = 0;
    for (int w = 0; w < workers; ++w) {
      const int in_cell = count[w][c];
      count[w][c] = g.cell_begin[c] + total;  // where worker w starts writing in cell c
      total += in_cell;
    }
    g.cell_begin[c + 1] = g.cell_begin[c] + total;
  }
  g.items.resize(g.cell_begin.back());
  parallel_chunks(n, workers, [&](std::size_t b, std::size_t e, int w) {
    for (std::size_t k = b; k < e; ++k)
      if (const Box box = box_of(k); gridded(box)) for_cells(box, [&](std::size_t c) { g.items[count[w][c]++] = static_cast<int>(k); });
  });
  for (const auto& list : unbounded) g.always.insert(g.always.end(), list.begin(), list.end());
  return g;
}

}  // namespace covmap::voronoi
