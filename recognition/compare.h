// covmap::recognition::compare_graphs — where two arc graphs differ (paper 5, §5: deciding "is it
// the MWVD?" by comparing the input with the recomputed diagram).
//
// Nodes are matched by position (a hash grid of cell size `tolerance`, linear time), arcs by their
// matched end nodes and their curve (circle centre and radius, or line, within the tolerance);
// full circles by their curve alone. Every unmatched node or arc of either graph is reported with
// its position; an unmatched arc of `b` that names sites also names the faces (regions of those
// sites) that `a` lacks there — e.g. an orphan face missing from a coverage map. Unmatched nodes
// and arcs lying entirely on the other graph (within the tolerance) are not differences: exactly
// degenerate inputs (tangencies, nodes of degree four) can be redrawn with another topology after
// any rounding of their sites.
#pragma once

#include <string>
#include <vector>

#include "core/diagram.h"

namespace covmap::recognition {

struct CompareOptions {
  // Relative to the extent (see horizon): positions and curve parameters closer than this are
  // the same. Far from the sites the allowance grows with the distance (in units of the extent):
  // there nodes of nearly tangent bisectors and huge circles move in proportion to it when the
  // sites are rounded.
  double relative_tolerance = 1e-7;
  // The horizon, relative to the extent (the first graph's nodes and both graphs' sites; the
  // first graph is the reference, e.g. the input of recognition): nodes farther than this
  // from their centre count as points at infinity, and arcs entirely beyond it are not compared.
  // Out there, parallel bisectors of a degenerate input meet after any rounding of the sites
  // (three collinear equal-weight sites moved by 1e-15 give a node 1e15 away), which no
  // double-precision graph can decide.
  double horizon = 1e6;
};

// A is the first graph (recognition: the input), B the second (recognition: the diagram recomputed
// from the reconstructed sites). FaceOnlyInB: a face of B none of whose arcs A has (recognition's
// MWVD check only: a face missing from the input, e.g. an orphan face).
enum class DifferenceKind { NodeOnlyInA, NodeOnlyInB, ArcOnlyInA, ArcOnlyInB, FaceOnlyInB };
const char* to_string(DifferenceKind kind);

struct Difference {
  DifferenceKind kind = DifferenceKind::NodeOnlyInA;
  int index = kNone;  // node, arc or face index in its graph
  double x = 0.0, y = 0.0;     // where (a node, a point of the arc, a point of the face)
  std::string message;
};

struct Comparison {
  std::size_t nodes_matched = 0;
  std::size_t arcs_matched = 0;
  std::vector<Difference> differences;
  bool equal() const { return differences.empty(); }
  std::string brief() const;
};

Comparison compare_graphs(const Diagram& a, const Diagram& b,
                          const CompareOptions& options = {});

}  // namespace covmap::recognition
