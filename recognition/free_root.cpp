// The free root of recognize() (paper 5, §3): when no node fixes any site, the root face's site
// ranges over a region, the intersection of generalized disks.
#include <algorithm>
#include <deque>
#include <sstream>

#include "mobius/feasible_region.h"
#include "mobius/mobius.h"
#include "recognition/recognize_stages.h"

namespace covmap::recognition::stages {
namespace {

// The root is an unbounded face when there is one.
int root_face(const Diagram& g, const LargeVector<char>& outside) {
  const int faces = static_cast<int>(g.faces.size());
  for (int f = 0; f < faces; ++f)
    if (!outside[f] && !g.faces[f].bounded) return f;
  for (int f = 0; f < faces; ++f)
    if (!outside[f]) return f;
  return kNone;
}

}  // namespace

// Paper 5 §3: the sites are fixed by one root site through the inversions along a spanning tree of
// the faces, and each arc asks for its two sites to lie on its two sides. Pulled back to the root
// by the composed (anti-)Möbius map, each such demand is a generalized disk for the root's site.
std::vector<mobius::GeneralizedCircle> pulled_back_bounds(const TracedGraph& t, int root) {
  const Diagram& g = t.g;
  std::vector<mobius::GeneralizedCircle> bounds;
  const int faces = static_cast<int>(g.faces.size());
  LargeVector<mobius::Mobius> to_face(faces);
  LargeVector<char> reached(faces, 0), arc_used(g.arcs.size(), 0);
  std::deque<int> queue{root};
  reached[root] = 1;
  while (!queue.empty()) {
    const int f = queue.front();
    queue.pop_front();
    for (const auto cycle : face_cycles(g, f))
      for (const HalfArc& h : cycle) {
        const Arc& arc = g.arcs[h.arc];
        if (arc.frame || arc_used[h.arc]) continue;
        arc_used[h.arc] = 1;
        const mobius::GeneralizedCircle c = curve_of(arc);
        const bool f_left_is_inside = std::holds_alternative<Line>(arc.curve) ? h.forward : (h.forward == arc.ccw);
        const mobius::GeneralizedCircle side = f_left_is_inside ? c : mobius::GeneralizedCircle{-c.A, -c.B, -c.C};
        bounds.push_back(to_face[f].inverse().apply(side));
        const int other = t.face_of_half[half_id({h.arc, !h.forward})];
        if (other == kNone || reached[other]) continue;
        reached[other] = 1;
        to_face[other] = mobius::Mobius::inversion(c).after(to_face[f]);
        queue.push_back(other);
      }
  }
  return bounds;
}

std::variant<SiteRegion, Rejection> free_root_region(const TracedGraph& t, const Box& extent) {
  const Diagram& g = t.g;
  const double scale = t.scale;
  SiteRegion region;
  region.face = root_face(g, t.outside);
  if (region.face == kNone) return Rejection{"the graph has no face that could hold a site", std::nullopt};
  region.bounds = pulled_back_bounds(t, region.face);
  const mobius::FeasibleRegion fr = mobius::feasible_region(region.bounds, mobius::Complex(extent.centre().x, extent.centre().y),
                                            std::max(2.0 * scale, 1.0));
  if (fr.empty) {
    RecognitionFailure fail;
    fail.face = region.face;
    std::ostringstream msg;
    msg << "no position for the site of face " << region.face << " puts every pair of sites on the two sides of their arc ("
        << region.bounds.size() << " conditions, paper 5 §3: the solution set is empty)";
    fail.message = msg.str();
    return Rejection{fail.message, fail};
  }
  region.representative = {fr.representative.real(), fr.representative.imag()};
  region.margin = fr.margin;
  return region;
}

}  // namespace covmap::recognition::stages
