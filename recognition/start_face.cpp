// The start face of recognize(): the face whose nodes give the most constraints on its site.
#include <algorithm>

#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {

StartFace start_face(const TracedGraph& t) {
  const Diagram& g = t.g;
  const int faces = static_cast<int>(g.faces.size());
  int start = -1;
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
    if (found.size() > constraints.size()) start = f, constraints = std::move(found);
    if (constraints.size() >= 6) break;  // plenty: a bounded amount of work for the start face
  }
  return StartFace{start, std::move(constraints)};
}

}  // namespace covmap::recognition::stages
