// Small edits on a Diagram shared by the engine and by graph repair.
#pragma once

#include "core/diagram.h"

namespace covmap::voronoi {

// Removes nodes that no arc references and renumbers the arcs' ends.
void drop_unused_nodes(Diagram& d);

}  // namespace covmap::voronoi
