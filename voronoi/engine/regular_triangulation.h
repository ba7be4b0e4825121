// The 3D regular triangulation of the lifted sites (see lifted_traits.h), with integer ids on
// cells so per-cell and per-facet data can live in plain arrays.
//
// SpatialTriangulation, in every dimension. No lifted site is ever hidden (each owns a
// neighbourhood of itself, so it has a power cell among any subset of the sites), so cells keep no
// list of hidden points: CGAL's default std::list costs 24 bytes in each of the ~6.5 million cells
// of 10^6 sites. With Discard_hidden_points the container is only asked for an empty range, and
// cells are 72 bytes (4 vertex and 4 neighbour handles, the id, the empty member) instead of 96: a
// quarter less memory to fault in and to walk through, the same triangulation in the same order
// (the extractors read cells in CGAL's container order, which the layout does not change;
// tests/voronoi/spatial_triangulation_test.cpp compares the cells in every dimension). Coplanar
// lifted sites (dimension ≤ 2: equal weights, w² affine in position, fewer than four sites) kept
// CGAL's default cells while the planar extractor read CGAL's edge iterator, which picks the cell
// reporting an edge by comparing cell addresses; it no longer does, and the lean cells gave the
// same files there (equal weights and grids, 2·10^5 sites: the same time, 4 % less peak memory).
//
// RegularTriangulation, CGAL's default cells, is the reference the tests compare against.
#pragma once

#include <CGAL/Hidden_point_memory_policy.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>

#include "voronoi/engine/lifted_traits.h"

namespace covmap::voronoi::engine {

// The hidden-point container of SpatialTriangulation's cells: always empty.
struct NoHiddenPoints {
  using value_type = RawWeightedPoint;
  using iterator = RawWeightedPoint*;
  using const_iterator = const RawWeightedPoint*;
  iterator begin() { return nullptr; }
  iterator end() { return nullptr; }
  const_iterator begin() const { return nullptr; }
  const_iterator end() const { return nullptr; }
};

using VertexBase = CGAL::Regular_triangulation_vertex_base_3<LiftedTraits>;
using CellBase = CGAL::Triangulation_cell_base_with_info_3<
    int, LiftedTraits, CGAL::Regular_triangulation_cell_base_3<LiftedTraits>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using RegularTriangulation = CGAL::Regular_triangulation_3<LiftedTraits, Tds>;

using LeanCellBase = CGAL::Regular_triangulation_cell_base_3<
    LiftedTraits, CGAL::Triangulation_cell_base_with_info_3<int, LiftedTraits>, CGAL::Discard_hidden_points,
    NoHiddenPoints>;
using SpatialTriangulation =
    CGAL::Regular_triangulation_3<LiftedTraits, CGAL::Triangulation_data_structure_3<VertexBase, LeanCellBase>>;

template <class VertexHandle>
int site_of(VertexHandle v) {
  return static_cast<int>(v->point().weight());
}

}  // namespace covmap::voronoi::engine
