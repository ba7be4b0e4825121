// The frame of a clipped map in recognize(): nodes on it (where the map was cut), the face outside
// it, and its polygon for clipping the recomputed diagram.
#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {

FrameMarks frame_marks(const Diagram& g, const LargeVector<int>& face_of_half) {
  FrameMarks m;
  // Nodes on the frame are where the map was cut, not where sites meet: they give no solution
  // circle.
  m.on_frame.assign(g.nodes.size(), 0);
  for (const Arc& a : g.arcs)
    if (a.frame)
      for (int v : {a.from, a.to})
        if (v != kNone) m.on_frame[v] = 1;
  // The face outside the frame (on the right of frame arcs) has no site.
  m.outside.assign(g.faces.size(), 0);
  for (std::size_t a = 0; a < g.arcs.size(); ++a)
    if (g.arcs[a].frame && face_of_half[2 * a + 1] != kNone) m.outside[face_of_half[2 * a + 1]] = 1;
  return m;
}

// The clip polygon of a clipped graph: its own if stated, else the frame arcs followed from node to
// node (counter-clockwise, as frame arcs keep the inside on their left).
std::vector<Point> clip_polygon_of(const Diagram& g) {
  if (!g.clip.empty()) return g.clip;
  std::vector<int> next_arc(g.nodes.size(), kNone);
  int first = kNone;
  for (std::size_t a = 0; a < g.arcs.size(); ++a)
    if (g.arcs[a].frame && g.arcs[a].from != kNone) {
      next_arc[g.arcs[a].from] = static_cast<int>(a);
      if (first == kNone) first = static_cast<int>(a);
    }
  std::vector<Point> poly;
  for (int a = first, guard = 0; a != kNone && guard <= static_cast<int>(g.arcs.size()); ++guard) {
    const auto& n = g.nodes[g.arcs[a].from];
    poly.push_back({n.x, n.y});
    a = next_arc[g.arcs[a].to];
    if (a == first) break;
  }
  return poly;
}

}  // namespace covmap::recognition::stages
