#include "voronoi/engine/flat_triangulation.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>
#include <vector>

#include "core/parallel.h"
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace covmap::voronoi::engine {

void trim_heap() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

LargeVector<int> morton_ranks(const std::vector<Site>& sites) {
  constexpr int kBits = 16;
  constexpr double kScale = 1 << (kBits - 1);
  auto quantize = [&](double v) {
    return static_cast<std::uint32_t>(std::clamp((v + 1) * kScale, 0.0, 2 * kScale - 1));
  };
  auto spread = [](std::uint64_t v) {  // bit b of v to bit 2b
    v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
    v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
    v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
    v = (v | (v << 2)) & 0x3333333333333333ull;
    v = (v | (v << 1)) & 0x5555555555555555ull;
    return v;
  };
  LargeVector<std::uint64_t> keys(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i)
    keys[i] = ((spread(quantize(sites[i].x)) | (spread(quantize(sites[i].y)) << 1)) << 32) | i;
  std::sort(keys.begin(), keys.end());
  LargeVector<int> rank(sites.size());
  for (std::size_t r = 0; r < keys.size(); ++r) rank[keys[r] & 0xFFFFFFFFu] = static_cast<int>(r);
  return rank;
}

FlatVertices flat_vertices(const std::vector<Site>& sites) {
  FlatVertices v;
  v.rank = morton_ranks(sites);
  v.points.resize(sites.size());
  v.vertex_site.resize(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) {
    v.points[v.rank[i]] = RawPoint(sites[i].x, sites[i].y, sites[i].weight);
    v.vertex_site[v.rank[i]] = static_cast<int>(i);
  }
  return v;
}

namespace {

// A cell's vertices in canonical order: their ranks (kInfiniteVertex, below every rank, for the
// infinite vertex) increasing, the last two swapped if that order is an odd permutation of CGAL's,
// so that the cell stays positively oriented (CGAL's neighbour rules, e.g. next_around_edge, and
// the extractor's orientation parity rely on it). `from[k]`: CGAL's index of the vertex stored
// at k. Four distinct vertices, so the order is a function of the vertex set alone.
struct CanonicalCell {
  std::array<int, 4> vertex;
  std::array<int, 4> from;
};

template <class CellHandle, class VertexHandle>
CanonicalCell canonical_cell(const CellHandle& c, const VertexHandle& infinite, const LargeVector<int>& rank) {
  CanonicalCell r;
  for (int k = 0; k < 4; ++k) {
    const VertexHandle v = c->vertex(k);
    r.vertex[k] = v == infinite ? kInfiniteVertex : rank[site_of(v)];
    r.from[k] = k;
  }
  bool odd = false;
  for (int i = 1; i < 4; ++i)  // insertion sort, counting transpositions
    for (int j = i; j > 0 && r.vertex[j - 1] > r.vertex[j]; --j) {
      std::swap(r.vertex[j - 1], r.vertex[j]);
      std::swap(r.from[j - 1], r.from[j]);
      odd = !odd;
    }
  if (odd) {
    std::swap(r.vertex[2], r.vertex[3]);
    std::swap(r.from[2], r.from[3]);
  }
  return r;
}

// The rank a cell is bucketed by: its lowest finite vertex's.
int bucket_of(const FlatCell& c) {
  return c.vertex[0] == kInfiniteVertex ? c.vertex[1] : c.vertex[0];
}

// Per cell, by its id (its place in CGAL's container order), its canonical vertices and its
// neighbours' ids; `rt` is cleared afterwards. The one sequential pass numbers the cells (info());
// then each cell is read once, in container order on all cores. The passes that number the cells
// canonically read only this copy: they visit cells in another order, and reading CGAL's scattered
// cells and vertices there would wait on memory.
template <class Triangulation>
LargeVector<FlatCell> cells_by_id(Triangulation& rt, const LargeVector<int>& rank) {
  const std::size_t n = rt.tds().number_of_cells();
  using CellHandle = typename Triangulation::Cell_handle;
  LargeVector<CellHandle> handles(n);
  int id = 0;
  for (auto c = rt.all_cells_begin(); c != rt.all_cells_end(); ++c, ++id) {
    c->info() = id;
    handles[id] = c;
  }
  LargeVector<FlatCell> by_id(n);  // sized without touching a page: every entry is written below
  const auto infinite = rt.infinite_vertex();
  parallel_chunks(n, worker_count(n), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t o = begin; o < end; ++o) {
      const CanonicalCell c = canonical_cell(handles[o], infinite, rank);
      FlatCell& f = by_id[o];
      f.vertex = c.vertex;
      for (int k = 0; k < 4; ++k) f.neighbor[k] = handles[o]->neighbor(c.from[k])->info();
    }
  });
  LargeVector<CellHandle>().swap(handles);
  rt.clear();
  // The triangulation's blocks are unmapped as it is cleared (engine/cell_arena.h); what it
  // allocated besides (CGAL's copy of the points, the spatial sort's buffers) may stay in glibc's
  // heaps, resident behind the arrays allocated since: returned to the system.
  trim_heap();
  return by_id;
}

// The canonical numbering of the cells `by_id` (vertex ranks below `ranks`): by the rank of their
// lowest finite vertex (a counting sort), then each rank's cells (a few dozen at most) by their
// canonical vertex arrays.
struct Numbering {
  LargeVector<int> order;   // per canonical number, the id
  LargeVector<int> number;  // per id, the canonical number
};
Numbering canonical_numbering(const LargeVector<FlatCell>& by_id, std::size_t ranks) {
  const std::size_t n = by_id.size();
  Numbering r;
  r.order.resize(n);
  r.number.resize(n);
  LargeVector<int> first(ranks + 1, 0);
  for (std::size_t o = 0; o < n; ++o) ++first[bucket_of(by_id[o]) + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  {
    LargeVector<int> next(first.begin(), first.end() - 1);
    for (std::size_t o = 0; o < n; ++o) r.order[next[bucket_of(by_id[o])]++] = static_cast<int>(o);
  }
  parallel_chunks(ranks, worker_count(ranks), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t b = begin; b < end; ++b) {
      std::sort(r.order.begin() + first[b], r.order.begin() + first[b + 1],
                [&](int x, int y) { return by_id[x].vertex < by_id[y].vertex; });
      for (int k = first[b]; k < first[b + 1]; ++k) r.number[r.order[k]] = k;
    }
  });
  return r;
}

}  // namespace

template <class Triangulation>
FlatTriangulation flatten_triangulation(const std::vector<Site>& sites, FlatVertices vertices, Triangulation& rt) {
  FlatTriangulation flat;
  flat.points = std::move(vertices.points);
  flat.vertex_site = std::move(vertices.vertex_site);
  {
    LargeVector<FlatCell> by_id = cells_by_id(rt, vertices.rank);
    LargeVector<int>().swap(vertices.rank);
    const Numbering numbering = canonical_numbering(by_id, sites.size());
    const std::size_t n = by_id.size();
    // Sized without touching a page: every entry is written here, on all cores.
    flat.cells.resize(n);
    flat.flags.resize(n);
    parallel_chunks(n, worker_count(n), [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t k = begin; k < end; ++k) {
        const FlatCell& c = by_id[numbering.order[k]];
        FlatCell& f = flat.cells[k];
        f.vertex = c.vertex;
        for (int m = 0; m < 4; ++m) f.neighbor[m] = numbering.number[c.neighbor[m]];
        flat.flags[k] = c.vertex[0] == kInfiniteVertex ? kInfiniteCell : 0;
      }
    });
  }
  // The copy by id and the numbering go back to the system, not to core/large_buffer.h's cache,
  // where they would stay resident under the extractor's smaller arrays and raise the peak.
  release_large_buffers();
  return flat;
}

template FlatTriangulation flatten_triangulation(const std::vector<Site>&, FlatVertices, SpatialTriangulation&);

}  // namespace covmap::voronoi::engine
