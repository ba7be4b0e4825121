// Repairs of input arc graphs that recognition can make without guessing, each reported, and the
// one preparation of an input graph that every caller of recognize() shares (the CLI, the service,
// library users).
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

// Makes an arc graph read from a file ready for recognize(): its faces are dropped (recognition
// traces them by geometry); its sites and arc labels are kept for recognize() to compare with its
// reconstruction (input_sites.h), which it makes from the arcs alone; nodes of degree 2 on one
// curve are merged away where their two arcs name the same sites (merge_degree_two_nodes, with a tolerance of tolerance::kRepairRelative times the
// largest coordinate magnitude, at least 1). Returns what was repaired.
std::vector<Repair> prepare_input_graph(Diagram& g);

// The arc reversed: same points, opposite direction of travel, sides swapped.
Arc reversed(Arc a);

}  // namespace covmap::recognition
