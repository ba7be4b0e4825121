#include "voronoi/engine/flat_triangulation.h"

#include <algorithm>
#include <numeric>

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

template <class Triangulation>
FlatTriangulation flatten_triangulation(const std::vector<Site>& sites, FlatVertices vertices, Triangulation& rt) {
  FlatTriangulation flat;
  const std::size_t n = rt.tds().number_of_cells();
  // Sized without touching a page: every entry is written below, on all cores.
  flat.cells.resize(n);
  flat.orig.resize(n);
  flat.by_orig.resize(n);
  flat.flags.resize(n);
  const LargeVector<int> rank = std::move(vertices.rank);
  flat.points = std::move(vertices.points);
  flat.vertex_site = std::move(vertices.vertex_site);
  // The one sequential pass over CGAL's container: each cell's id (its place in the container's
  // order) and handle. The passes after it read the cells through the handles, on all cores, each
  // cell's entries written by one worker.
  using CellHandle = typename Triangulation::Cell_handle;
  LargeVector<CellHandle> handles(n);
  int id = 0;
  for (auto c = rt.all_cells_begin(); c != rt.all_cells_end(); ++c, ++id) {
    c->info() = id;
    handles[id] = c;
  }
  const int workers = worker_count(n);
  const auto infinite = rt.infinite_vertex();
  // Cells by the rank of their first-ranked site: a counting sort, CGAL's order within a rank.
  parallel_chunks(n, workers, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t o = begin; o < end; ++o) {
      int lowest = static_cast<int>(sites.size());
      for (int k = 0; k < 4; ++k)
        if (handles[o]->vertex(k) != infinite) lowest = std::min(lowest, rank[site_of(handles[o]->vertex(k))]);
      flat.by_orig[o] = lowest;
    }
  });
  LargeVector<int> first(sites.size() + 1, 0);
  for (std::size_t o = 0; o < n; ++o) ++first[flat.by_orig[o] + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  for (std::size_t o = 0; o < n; ++o) {
    const int cell = first[flat.by_orig[o]]++;
    flat.by_orig[o] = cell;
    flat.orig[cell] = static_cast<int>(o);
  }
  parallel_chunks(n, workers, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t o = begin; o < end; ++o) {
      const CellHandle c = handles[o];
      const int cell = flat.by_orig[o];
      FlatCell& f = flat.cells[cell];
      bool at_infinity = false;
      for (int k = 0; k < 4; ++k) {
        const typename Triangulation::Vertex_handle v = c->vertex(k);
        at_infinity |= v == infinite;
        f.vertex[k] = v == infinite ? kInfiniteVertex : rank[site_of(v)];
        f.neighbor[k] = flat.by_orig[c->neighbor(k)->info()];
      }
      flat.flags[cell] = at_infinity ? kInfiniteCell : 0;
    }
  });
  LargeVector<CellHandle>().swap(handles);
  rt.clear();
  // The triangulation's blocks are unmapped as it is cleared (engine/cell_arena.h); what it
  // allocated besides (CGAL's copy of the points, the spatial sort's buffers) may stay in glibc's
  // heaps, resident behind the arrays allocated since: returned to the system.
  trim_heap();
  return flat;
}

template FlatTriangulation flatten_triangulation(const std::vector<Site>&, FlatVertices, SpatialTriangulation&);

}  // namespace covmap::voronoi::engine
