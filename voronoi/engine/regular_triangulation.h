// The 3D regular triangulation of the lifted sites (see lifted_traits.h), with integer ids on
// cells so per-cell and per-facet data can live in plain arrays.
#pragma once

#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>

#include "voronoi/engine/lifted_traits.h"

namespace covmap::voronoi::engine {

using VertexBase = CGAL::Regular_triangulation_vertex_base_3<LiftedTraits>;
using CellBase = CGAL::Triangulation_cell_base_with_info_3<
    int, LiftedTraits, CGAL::Regular_triangulation_cell_base_3<LiftedTraits>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using RegularTriangulation = CGAL::Regular_triangulation_3<LiftedTraits, Tds>;

inline int site_of(RegularTriangulation::Vertex_handle v) {
  return static_cast<int>(v->point().weight());
}

}  // namespace covmap::voronoi::engine
