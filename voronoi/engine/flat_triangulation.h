// The regular triangulation as the spatial extractor reads it (internal to the engine): copied once
// into flat arrays and the CGAL structure released, so that the extractor's passes read 32-byte
// cells by index instead of chasing ~100-byte cells through pointers.
//
// Layout (why: extract_spatial.cpp's top comment). Vertices are numbered by their sites' Morton
// (Z-order) rank and their points stored in that order. The cells are numbered canonically: by the
// ranks of their vertices, whatever order CGAL inserted the sites in or stores its cells and their
// vertices in. A cell's vertices are stored in increasing rank (the infinite vertex first), the
// last two swapped when that order is an odd permutation of CGAL's, so every cell keeps CGAL's
// positive orientation; cells are stored by the rank of their first finite vertex (a counting
// sort), and within one rank by their vertex arrays. The extractor decides everything that orders
// its output (node numbers, arc order, which cell of a facet computes it, where a walk starts) and
// every construction's order of sites from these numbers alone, so its output is a function of the
// triangulation as a complex (regular_triangulation.h: it does not depend on the insertion order).
// Points are the same doubles the triangulation holds.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/large_buffer.h"
#include "core/diagram.h"
#include "voronoi/engine/regular_triangulation.h"

namespace covmap::voronoi::engine {

inline constexpr int kInfiniteVertex = -1;  // the infinite vertex in FlatCell::vertex

// One cell: its vertices (vertex ids, kInfiniteVertex for the infinite vertex) and, opposite
// vertex k, its neighbour's cell.
struct FlatCell {
  std::array<int, 4> vertex;
  std::array<int, 4> neighbor;
};

// Per cell flags, apart from the power vertices: the walks read only these.
enum CellFlag : std::uint8_t {
  kInfiniteCell = 1,
  kZeroVertex = 2,  // the vertex is a zero point: on the paraboloid, or the direction U
};

struct FlatTriangulation {
  LargeVector<FlatCell> cells;       // in canonical order (see the top of the file)
  LargeVector<RawPoint> points;      // per vertex id, its site's (x, y, w)
  LargeVector<int> vertex_site;      // per vertex id, its site
  LargeVector<std::uint8_t> flags;   // per cell: kInfiniteCell set, nothing else yet
};

// Returns the memory freed into malloc's heaps to the system (glibc's malloc_trim; elsewhere
// nothing).
void trim_heap();

// Per site, its rank along a Morton curve of the sites' positions, which lie in (-1, 1)
// (build_diagram scales them so). Only memory layout depends on it.
LargeVector<int> morton_ranks(const std::vector<Site>& sites);

// The vertex side of the flat copy, which needs only the sites: their Morton ranks, and per vertex
// id its point and site. build_diagram computes it beside the triangulation.
struct FlatVertices {
  LargeVector<int> rank;         // per site, its vertex id
  LargeVector<RawPoint> points;  // per vertex id, its site's (x, y, w)
  LargeVector<int> vertex_site;  // per vertex id, its site
};
FlatVertices flat_vertices(const std::vector<Site>& sites);

// The flat copy of `rt` (a 3-dimensional triangulation of `sites`, whose flat_vertices are
// `vertices`); `rt` is cleared afterwards. Defined for SpatialTriangulation.
template <class Triangulation>
FlatTriangulation flatten_triangulation(const std::vector<Site>& sites, FlatVertices vertices, Triangulation& rt);

}  // namespace covmap::voronoi::engine
