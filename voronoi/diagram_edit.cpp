#include "voronoi/diagram_edit.h"

namespace covmap::voronoi {

void drop_unused_nodes(Diagram& d) {
  std::vector<int> remap(d.nodes.size(), kNone);
  for (const Arc& a : d.arcs)
    for (int n : {a.from, a.to})
      if (n != kNone) remap[n] = 0;
  int next = 0;
  for (std::size_t k = 0; k < d.nodes.size(); ++k)
    if (remap[k] != kNone) {
      remap[k] = next;
      d.nodes[next++] = d.nodes[k];
    }
  d.nodes.resize(next);
  for (Arc& a : d.arcs) {
    if (a.from != kNone) a.from = remap[a.from];
    if (a.to != kNone) a.to = remap[a.to];
  }
}

}  // namespace covmap::voronoi
