// The start face of recognize(): the face whose nodes fix its site best.
#include <algorithm>
#include <utility>

#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {
namespace {

// How far a node lies outside the graph's extent, in extents: its constraint is only as accurate as
// that distance (a node 1e13 extents out, where the parallel-ish bisectors of nearly collinear sites
// meet, fixes nothing near the graph).
double remoteness(const TracedGraph& t, int node) {
  return t.extent.distance_to({t.g.nodes[node].x, t.g.nodes[node].y}) / t.scale;
}

// Constraints from nodes within one extent of the graph whose fixed sets differ: mirror-image nodes
// of collinear sites, or two nodes of one split degree-four node, repeat one solution circle.
int distinct_near(const TracedGraph& t, const std::vector<Constraint>& cs) {
  std::vector<const Constraint*> kept;
  for (const Constraint& c : cs) {
    if (remoteness(t, c.node) > 1.0) continue;
    const bool repeat = c.is_circle && std::any_of(kept.begin(), kept.end(), [&](const Constraint* k) {
      return k->is_circle && same_circle(k->circle, c.circle, t);
    });
    if (!repeat) kept.push_back(&c);
  }
  return static_cast<int>(kept.size());
}

}  // namespace

// Faces are ranked by the distinct constraints of their near nodes (three fix a point by any
// measure), then by their number of constraints; each face's constraints are listed nearest node
// first, so that the candidates come from the accurate ones (candidates.cpp takes pairs in order).
StartFace start_face(const TracedGraph& t) {
  const Diagram& g = t.g;
  const int faces = static_cast<int>(g.faces.size());
  constexpr int kEnough = 3;
  int start = -1, best_distinct = -1;
  std::vector<Constraint> constraints;
  for (int f = 0; f < faces; ++f) {
    if (t.outside[f]) continue;
    std::vector<Constraint> found;
    std::vector<int> seen_nodes;
    for (const auto cycle : face_cycles(g, f))
      for (const HalfArc& hh : cycle) {
        const Arc& arc = g.arcs[hh.arc];
        const int v = hh.forward ? arc.from : arc.to;  // hh starts at v
        if (v == kNone || t.on_frame[v] || arc.frame) continue;
        if (std::find(seen_nodes.begin(), seen_nodes.end(), v) != seen_nodes.end()) continue;
        seen_nodes.push_back(v);
        if (auto c = node_constraint(t, f, half_id(hh)); c && !c->any) {
          c->node = v;
          found.push_back(*c);
        }
      }
    std::stable_sort(found.begin(), found.end(),
                     [&](const Constraint& a, const Constraint& b) { return remoteness(t, a.node) < remoteness(t, b.node); });
    const int distinct = std::min(distinct_near(t, found), kEnough);
    if (std::pair(distinct, found.size()) > std::pair(best_distinct, constraints.size()))
      start = f, best_distinct = distinct, constraints = std::move(found);
    // Plenty: a bounded amount of work for the start face.
    if (best_distinct >= kEnough && (constraints.size() >= 6 || f >= 256)) break;
  }
  return StartFace{start, std::move(constraints)};
}

}  // namespace covmap::recognition::stages
