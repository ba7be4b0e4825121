#include "voronoi/engine/flat_triangulation.h"

#include <algorithm>
#include <numeric>
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
  flat.cells.resize(n);
  flat.orig.resize(n);
  flat.by_orig.resize(n);
  flat.flags.assign(n, 0);
  const LargeVector<int> rank = std::move(vertices.rank);
  flat.points = std::move(vertices.points);
  flat.vertex_site = std::move(vertices.vertex_site);
  // Cells by the rank of their first-ranked site: a counting sort, CGAL's order within a rank.
  LargeVector<int> first(sites.size() + 1, 0);
  int id = 0;
  for (auto c = rt.all_cells_begin(); c != rt.all_cells_end(); ++c) {
    int lowest = static_cast<int>(sites.size());
    for (int k = 0; k < 4; ++k)
      if (!rt.is_infinite(c->vertex(k))) lowest = std::min(lowest, rank[site_of(c->vertex(k))]);
    c->info() = id;
    flat.by_orig[id++] = lowest;
    ++first[lowest + 1];
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  for (std::size_t o = 0; o < n; ++o) {
    const int cell = first[flat.by_orig[o]]++;
    flat.by_orig[o] = cell;
    flat.orig[cell] = static_cast<int>(o);
  }
  id = 0;
  for (auto c = rt.all_cells_begin(); c != rt.all_cells_end(); ++c, ++id) {
    const int cell = flat.by_orig[id];
    FlatCell& f = flat.cells[cell];
    for (int k = 0; k < 4; ++k) {
      const typename Triangulation::Vertex_handle v = c->vertex(k);
      f.vertex[k] = rt.is_infinite(v) ? kInfiniteVertex : rank[site_of(v)];
      f.neighbor[k] = flat.by_orig[c->neighbor(k)->info()];
    }
    if (rt.is_infinite(c)) flat.flags[cell] = kInfiniteCell;
  }
  rt.clear();
  // CGAL's cells live in blocks of at most a few MB, which glibc may have placed in its heaps
  // rather than in mappings of their own (it stops mapping blocks below the largest one freed so
  // far); freed there, they would stay resident, ~0.45 GB at 10^6 sites, behind the arrays
  // allocated since. Return them to the system.
  trim_heap();
  return flat;
}

template FlatTriangulation flatten_triangulation(const std::vector<Site>&, FlatVertices, SpatialTriangulation&);

}  // namespace covmap::voronoi::engine
