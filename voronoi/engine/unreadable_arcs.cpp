// Arcs too short to be read from their rounded end nodes.
//
// Nodes are rounded once, so two nodes closer than an ulp or two (a node of degree 4 of nearly
// cocircular sites, split by a perturbation of one ulp; the two crossings of nearly tangent
// bisectors) may come out equal or in the wrong order. A reader takes a circle arc's sweep from
// its end nodes, so a tiny arc between them would read as almost the whole circle (and a
// near-full arc as a tiny one). Where the rounded nodes of a circle's arcs do not turn around it
// once (self_check.h), arcs whose ends are within rounding of each other are collapsed: their end
// nodes become one node, which is what the diagram is at the resolution of doubles, and each arc
// between the merged nodes is dropped if it was the tiny piece or kept as a loop through the node
// if it was the near-full one. Which of the two it was is read off the circle's far side, where
// the answer is not close: the point opposite the node is on the arc exactly when the arc's sites
// are the nearest there.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "voronoi/diagram_edit.h"
#include "voronoi/engine.h"
#include "voronoi/engine/self_check.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi::engine {
namespace {

enum class Piece { Tiny, NearFull };

// Whether the circle arc `a`, whose ends are (nearly) the node p, is the tiny or the near-full
// piece of its circle: is the antipode of p owned by the arc's sites? Brute force over the sites
// (this is rare); throws EngineFailure when the ownership there is too close to call.
Piece classify(const Diagram& d, const Arc& a, const Node& p) {
  const Circle& c = std::get<Circle>(a.curve);
  const double px = 2 * c.cx - p.x, py = 2 * c.cy - p.y;
  auto distance = [&](const Site& s) { return std::hypot(px - s.x, py - s.y) / s.weight; };
  const double own = std::min(distance(d.sites[a.left_site]), distance(d.sites[a.right_site]));
  double other = HUGE_VAL;
  for (std::size_t s = 0; s < d.sites.size(); ++s)
    if (static_cast<int>(s) != a.left_site && static_cast<int>(s) != a.right_site)
      other = std::min(other, distance(d.sites[s]));
  if (other > own * (1 + tolerance::kPieceProbeMargin)) return Piece::NearFull;
  if (other < own * (1 - tolerance::kPieceProbeMargin)) return Piece::Tiny;
  throw EngineFailure("the engine cannot tell whether an arc of sites " + d.sites[a.left_site].id + " and " +
                      d.sites[a.right_site].id + " whose ends round to one point is tiny or almost its whole circle");
}

}  // namespace

void collapse_unreadable_arcs(Diagram& d) {
  const double extent = site_extent(d.sites);
  std::vector<int> parent(d.nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  bool merged = false;
  for (std::size_t begin = 0, end = 0; begin < d.arcs.size(); begin = end) {
    end = pair_run_end(d, begin);
    if (!std::holds_alternative<Circle>(d.arcs[begin].curve) || circle_winding(d, begin, end) == 1) continue;
    for (std::size_t k = begin; k < end; ++k) {
      const Arc& a = d.arcs[k];
      if (a.from == kNone || a.from == a.to) continue;
      const Node& p = d.nodes[a.from];
      const Node& q = d.nodes[a.to];
      const double magnitude = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(q.x), std::fabs(q.y)});
      if (std::hypot(q.x - p.x, q.y - p.y) > allowed_off(extent, magnitude)) continue;
      parent[find(a.from)] = find(a.to);
      merged = true;
    }
  }
  if (!merged) return;
  // Every arc between merged nodes (of any site pair) was tiny or near-full.
  std::vector<Arc> kept;
  kept.reserve(d.arcs.size());
  for (Arc a : d.arcs) {
    const bool was_loop = a.from == a.to;
    if (a.from != kNone) a.from = find(a.from);
    if (a.to != kNone) a.to = find(a.to);
    const bool collapsed = a.from != kNone && a.from == a.to && !was_loop;
    if (collapsed && (std::holds_alternative<Line>(a.curve) || classify(d, a, d.nodes[a.from]) == Piece::Tiny)) continue;
    kept.push_back(a);
  }
  d.arcs.swap(kept);
}

}  // namespace covmap::voronoi::engine
