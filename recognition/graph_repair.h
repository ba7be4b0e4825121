// Repairs of input arc graphs that recognition can make without guessing, each reported.
#pragma once

#include <string>
#include <vector>

#include "core/diagram.h"

namespace covmap::recognition {

struct Repair {
  std::string what;
  double x = 0.0, y = 0.0;
};

// A node where exactly two arcs of one curve meet is no node of a bisector graph (every node has
// degree ≥ 3): the two arcs are joined into one, the node dropped. Two arcs "of one curve" have
// centre and radius (or line) equal within `tolerance` (a length). Returns what was done.
std::vector<Repair> merge_degree_two_nodes(Diagram& g, double tolerance);

// The arc reversed: same points, opposite direction of travel, sides swapped.
Arc reversed(Arc a);

}  // namespace covmap::recognition
