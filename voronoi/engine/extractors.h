// The extractors that read MWVD nodes and arcs off a regular triangulation of lifted sites, one
// per dimension of the triangulation.
#pragma once

#include <vector>

#include "voronoi/engine.h"
#include "voronoi/engine/regular_triangulation.h"

namespace covmap::voronoi::engine {

// Dimension 3: the general case (engine/extract_spatial.cpp). It copies what it needs of `rt` into
// flat arrays and clears `rt` (releasing its memory) before extracting.
void extract_spatial(const std::vector<Site>& sites, RegularTriangulation& rt, Diagram& out,
                     BuildStats& stats);
// Dimension 2: all lifted sites coplanar, e.g. all weights equal (engine/extract_planar.cpp).
void extract_planar(const std::vector<Site>& sites, RegularTriangulation& rt, Diagram& out,
                    BuildStats& stats);
// Dimension ≤ 1: every triangulation edge carries one whole bisector.
void extract_linear(const std::vector<Site>& sites, RegularTriangulation& rt, Diagram& out);

}  // namespace covmap::voronoi::engine
