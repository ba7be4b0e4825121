// covmap::recognition::compare_graphs — where two arc graphs differ (paper 5, §5: deciding "is it
// the MWVD?" by comparing the input with the recomputed diagram).
//
// Nodes are matched by position (a hash grid of cell size `tolerance`, linear time), arcs by their
// matched end nodes and their curve (circle centre and radius, or line, within the tolerance);
// full circles by their curve alone. Every unmatched node or arc of either graph is reported with
// its position; an unmatched arc of `b` that names sites also names the faces (regions of those
// sites) that `a` lacks there — e.g. an orphan face missing from a coverage map.
#pragma once

#include <string>
#include <vector>

#include "voronoi/diagram.h"

namespace covmap::recognition {

struct CompareOptions {
  // Relative to the diameter of the nodes of both graphs: positions and curve parameters closer
  // than this are the same.
  double relative_tolerance = 1e-7;
};

enum class DifferenceKind { NodeOnlyInA, NodeOnlyInB, ArcOnlyInA, ArcOnlyInB };
const char* to_string(DifferenceKind kind);

struct Difference {
  DifferenceKind kind = DifferenceKind::NodeOnlyInA;
  int index = voronoi::kNone;  // node or arc index in its graph
  double x = 0.0, y = 0.0;     // where (a node, or an arc's midpoint)
  std::string message;
};

struct Comparison {
  std::size_t nodes_matched = 0;
  std::size_t arcs_matched = 0;
  std::vector<Difference> differences;
  bool equal() const { return differences.empty(); }
  std::string brief() const;
};

Comparison compare_graphs(const voronoi::Diagram& a, const voronoi::Diagram& b,
                          const CompareOptions& options = {});

}  // namespace covmap::recognition
