// build_diagram with a chosen insertion order (internal to the engine): for tests that the diagram
// of spatial inputs does not depend on the order in which the sites enter the triangulation.
#pragma once

#include <span>

#include "voronoi/engine.h"
#include "voronoi/engine/regular_triangulation.h"

namespace covmap::voronoi::engine {

// build_diagram, with the sites of a 3-dimensional triangulation (lifted sites spanning space)
// inserted in `order`; the others are inserted in InsertionOrder::kSpatial3, as always (the planar
// extractor's output follows CGAL's container order). build_diagram passes the order it uses.
Diagram build_diagram_in_order(std::span<const Site> sites, InsertionOrder order, BuildStats* stats = nullptr);

}  // namespace covmap::voronoi::engine
