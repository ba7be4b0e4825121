// The regular triangulation as the spatial extractor reads it (internal to the engine): copied once
// into flat arrays and the CGAL structure released, so that the extractor's passes read 32-byte
// cells by index instead of chasing ~100-byte cells through pointers.
//
// Layout (why: extract_spatial.cpp's top comment). Vertices are numbered by their sites' Morton
// (Z-order) rank and their points stored in that order; cells are stored by the rank of their
// first-ranked vertex (a counting sort, CGAL's order within one rank). Each cell keeps its CGAL id
// (`orig`), which is what decides everything that orders the extractor's output, so the layout
// changes no decision and no order. Points are the same doubles the triangulation holds.
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
  LargeVector<FlatCell> cells;       // in spatial order
  LargeVector<int> orig;             // per cell, its id in CGAL's order
  LargeVector<int> by_orig;          // per CGAL id, the cell
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
