// The extractors that read MWVD nodes and arcs off a regular triangulation of lifted sites, one
// per dimension of the triangulation.
#pragma once

#include <vector>

#include "voronoi/engine.h"
#include "voronoi/engine/flat_triangulation.h"
#include "voronoi/engine/regular_triangulation.h"

namespace covmap::voronoi::engine {

// Dimension 3: the general case (engine/extract_spatial.cpp), from the flat copy of the
// triangulation (engine/flat_triangulation.h), which it consumes.
void extract_spatial(const std::vector<Site>& sites, FlatTriangulation flat, Diagram& out, BuildStats& stats);
// Dimension 2: all lifted sites coplanar, e.g. all weights equal (engine/extract_planar.cpp).
void extract_planar(const std::vector<Site>& sites, SpatialTriangulation& rt, Diagram& out,
                    BuildStats& stats);
// Dimension ≤ 1: every triangulation edge carries one whole bisector.
void extract_linear(const std::vector<Site>& sites, SpatialTriangulation& rt, Diagram& out);

}  // namespace covmap::voronoi::engine
