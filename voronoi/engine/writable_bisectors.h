// The last limit of the supported range (engine/limits.h, kBisectorUlps): every bisector the diagram
// uses must be wide enough, in units in the last place of its own coordinates, for its sides to be
// told apart once written. Which pairs of sites share a bisector is only known after construction.
#pragma once

#include "core/diagram.h"

namespace covmap::voronoi::engine {

// Throws InvalidSites naming both sites of every bisector narrower than the limit (d: the diagram
// in the engine's scaled frame, its sites scaled with it; sites[k].id are the input's ids).
void refuse_unwritable_bisectors(const Diagram& d);

}  // namespace covmap::voronoi::engine
