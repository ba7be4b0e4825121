#include "recognition/tolerances.h"
#include "recognition/graph_repair.h"

#include "voronoi/diagram_edit.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace covmap::recognition {


std::vector<Repair> prepare_input_graph(Diagram& g) {
  clear_faces(g);
  // Nodes of degree 2 on one curve are no nodes of a bisector graph: repaired and reported.
  double extent = 0;
  for (const auto& n : g.nodes) extent = std::max({extent, std::abs(n.x), std::abs(n.y)});
  return merge_degree_two_nodes(g, tolerance::kRepairRelative * std::max(extent, 1.0));
}

Arc reversed(Arc a) {
  std::swap(a.from, a.to);
  std::swap(a.left_site, a.right_site);
  if (auto* l = std::get_if<Line>(&a.curve)) {
    l->dx = -l->dx;
    l->dy = -l->dy;
  } else {
    a.ccw = !a.ccw;
  }
  return a;
}

namespace {

bool same_curve(const Arc& a, const Arc& b, double tol) {
  const auto* ca = std::get_if<Circle>(&a.curve);
  const auto* cb = std::get_if<Circle>(&b.curve);
  if (ca && cb)
    return a.ccw == b.ccw && std::hypot(ca->cx - cb->cx, ca->cy - cb->cy) <= tol &&
           std::abs(ca->r - cb->r) <= tol;
  if (ca || cb) return false;
  const auto& la = std::get<Line>(a.curve);
  const auto& lb = std::get<Line>(b.curve);
  const double na = std::hypot(la.dx, la.dy), nb = std::hypot(lb.dx, lb.dy);
  const double dot = (la.dx * lb.dx + la.dy * lb.dy) / (na * nb);
  const double offset = std::abs((lb.x - la.x) * la.dy - (lb.y - la.y) * la.dx) / na;
  return dot > 1.0 - tolerance::kSameDirectionCosine && offset <= tol;
}

}  // namespace

std::vector<Repair> merge_degree_two_nodes(Diagram& g, double tolerance) {
  std::vector<Repair> repairs;
  std::vector<char> alive(g.arcs.size(), 1);
  bool changed = true;
  while (changed) {
    changed = false;
    std::vector<std::vector<int>> at(g.nodes.size());
    for (std::size_t a = 0; a < g.arcs.size(); ++a) {
      if (!alive[a]) continue;
      if (g.arcs[a].from != kNone) at[g.arcs[a].from].push_back(static_cast<int>(a));
      if (g.arcs[a].to != kNone) at[g.arcs[a].to].push_back(static_cast<int>(a));
    }
    for (std::size_t v = 0; v < g.nodes.size(); ++v) {
      if (at[v].size() != 2 || at[v][0] == at[v][1]) continue;
      Arc a = g.arcs[at[v][0]], b = g.arcs[at[v][1]];
      if (a.to != static_cast<int>(v)) a = reversed(a);
      if (b.from != static_cast<int>(v)) b = reversed(b);
      if (a.to != static_cast<int>(v) || b.from != static_cast<int>(v)) continue;
      if (!same_curve(a, b, tolerance) || a.left_site != b.left_site ||
          a.right_site != b.right_site || a.frame != b.frame)
        continue;
      Arc merged = a;
      merged.to = b.to;
      if (merged.from == merged.to && merged.from == static_cast<int>(v)) merged.from = merged.to = kNone;
      g.arcs[at[v][0]] = merged;
      alive[at[v][1]] = 0;
      std::ostringstream m;
      m << "joined two arcs of one curve at a node of degree 2 (" << g.nodes[v].x << ", "
        << g.nodes[v].y << ")";
      repairs.push_back({m.str(), g.nodes[v].x, g.nodes[v].y});
      changed = true;
      break;  // incidence changed: recount
    }
  }
  // Drop dead arcs and unused nodes.
  std::vector<Arc> arcs;
  for (std::size_t a = 0; a < g.arcs.size(); ++a)
    if (alive[a]) arcs.push_back(g.arcs[a]);
  g.arcs = std::move(arcs);
  voronoi::drop_unused_nodes(g);
  return repairs;
}

}  // namespace covmap::recognition
