// Site collection in recognize(): the reconstruction from one site per face. Weights equal up to
// rounding are made equal (see RecognitionOptions::weight_snap), faces whose sites coincide within
// `tol` (orphans) share one site, and weights are normalised to a largest of 1. Sites are numbered
// by their first face. A face stated only by arcs read far out (an orphan 10¹⁰ extents out: nearly
// equal weights; huge circles, lines mirrored about far nodes) fixes its site only to tol times
// its spread (site_spread.h); when it is an orphan
// it joins the nearest face at least as well stated within that, and the site is placed by the
// group's best-stated face.
#include <algorithm>
#include <cmath>
#include <string>
#include <thread>
#include <utility>

#include "core/parallel.h"
#include "mobius/bisector_relation.h"
#include "recognition/recognize_stages.h"
#include "recognition/site_spread.h"
#include "voronoi/faces.h"

namespace covmap::recognition {
namespace {

using stages::FaceSite;
using stages::TracedGraph;

// A site's position keyed for the sweep in x.
struct Keyed {
  double x, y;
  int face;
  bool operator<(const Keyed& o) const { return x < o.x || (x == o.x && face < o.face); }
};

// Per face, its weight with weights equal up to weight_snap made equal.
void snap_weights(const LargeVector<FaceSite>& site, double weight_snap, LargeVector<double>& weight) {
  const int faces = static_cast<int>(site.size());
  LargeVector<std::pair<double, int>> order;
  order.reserve(faces);
  for (int f = 0; f < faces; ++f)
    if (site[f].assigned) order.emplace_back(site[f].weight, f);
  std::sort(order.begin(), order.end());  // (weight, face): no ties
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k > 0 && order[k].first - order[k - 1].first <= weight_snap * order[k].first) order[k].first = order[k - 1].first;
    weight[order[k].second] = order[k].first;
  }
}

// The assigned sites sorted by x (the positions travel with the sorted keys, so the sweep reads
// memory in order).
void sort_by_x(const LargeVector<FaceSite>& site, LargeVector<Keyed>& by_x) {
  const int faces = static_cast<int>(site.size());
  by_x.reserve(faces);
  for (int f = 0; f < faces; ++f)
    if (site[f].assigned) by_x.push_back({site[f].position.real(), site[f].position.imag(), f});
  std::sort(by_x.begin(), by_x.end());  // (x, face): no ties
}

// Coinciding sites through a sweep in x: each face joins the first earlier face (in face order)
// whose site lies within tol; a union over a window of width tol. Per face, the earliest face with
// the same site.
LargeVector<int> earliest_same_site(const LargeVector<Keyed>& by_x, int faces, double tol) {
  LargeVector<int> same_as(faces, kNone);
  const double tol2 = tol * tol;
  auto close = [&](const Keyed& a, const Keyed& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) <= tol2; };
  for (std::size_t k = 0; k < by_x.size(); ++k) {
    const Keyed& p = by_x[k];
    int earliest = p.face;
    for (std::size_t j = k; j-- > 0;) {
      const Keyed& e = by_x[j];
      if (p.x - e.x > tol) break;
      if (close(e, p)) earliest = std::min(earliest, same_as[e.face] == kNone ? e.face : same_as[e.face]);
    }
    for (std::size_t j = k + 1; j < by_x.size(); ++j) {
      const Keyed& e = by_x[j];
      if (e.x - p.x > tol) break;
      if (e.face < earliest && close(e, p)) earliest = e.face;
    }
    same_as[p.face] = earliest;
  }
  return same_as;
}

// The root of face f's group (groups: per face, an earlier face of its group or itself), with the
// path compressed; a group's root is its earliest face.
int group_of(LargeVector<int>& group, int f) {
  int root = f;
  while (group[root] != root) root = group[root];
  while (group[f] != root) f = std::exchange(group[f], root);
  return root;
}

// Whether face f of g contains p: an odd number of its boundary cycles around p, or an even one
// for a face without outer cycle (the unbounded face of holes only: not bounded, and no cycle
// through infinity).
bool face_contains(const Diagram& g, int f, Point p) {
  const FaceCycles cycles = face_cycles(g, f);
  if (cycles.size() == 0) return true;
  bool outer = g.faces[f].bounded;
  for (const HalfArc& h : cycles.front()) outer = outer || g.arcs[h.arc].from == kNone || g.arcs[h.arc].to == kNone;
  bool odd = false;
  for (const auto cycle : cycles) odd = odd != voronoi::cycle_contains(g, cycle, p);
  return outer ? odd : !odd;
}

// The faces stated less well than tol (spread > 1, rare: far faces) that are orphans — every
// site lies in its own region, so a face that does not contain its site is a piece of another
// face's region — join, each, the nearest face at least as well stated whose site lies within
// tol·spread and whose weight agrees to relative·spread: one link each, so such a face never joins
// two distinct sites into one. The window in x is found by bisection; only far faces pay for it.
void join_far_orphans(const TracedGraph& t, const LargeVector<Keyed>& by_x, const LargeVector<double>& spread,
                      const LargeVector<double>& weight, LargeVector<int>& group) {
  for (const Keyed& p : by_x) {
    const double s = spread[p.face];
    if (!(s > 1) || face_contains(t.g, p.face, {p.x, p.y})) continue;
    const double reach = t.tol * s;
    auto it = std::lower_bound(by_x.begin(), by_x.end(), Keyed{p.x - reach, 0, -1});
    int best = kNone;
    double best_d2 = INFINITY;
    for (; it != by_x.end() && it->x - p.x <= reach; ++it) {
      const int f = it->face;
      if (f == p.face || spread[f] > s) continue;
      const double d2 = (it->x - p.x) * (it->x - p.x) + (it->y - p.y) * (it->y - p.y);
      const bool weights_agree = std::abs(weight[f] - weight[p.face]) <= t.relative * s * std::max(weight[f], weight[p.face]);
      // And the twin's face must hold the orphan's site, as the face of a site's own region does:
      // two distinct sites of one weight 2e-3 of the extent apart, each face stated only far out
      // (exactly collinear sites), would be joined if the orphan test misread a face near nodes
      // 1e15 out.
      if (d2 <= reach * reach && weights_agree && (d2 < best_d2 || (d2 == best_d2 && f < best)) &&
          face_contains(t.g, f, {p.x, p.y}))
        best = f, best_d2 = d2;
    }
    if (best == kNone) continue;
    const int a = group_of(group, p.face), b = group_of(group, best);
    group[std::max(a, b)] = std::min(a, b);
  }
}

}  // namespace

LargeVector<double> face_spreads(const Diagram& g, const LargeVector<int>& face_of_half, Point centre, double scale) {
  LargeVector<double> spread(g.faces.size(), INFINITY);
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    if (g.arcs[a].frame) continue;
    const Arc& arc = g.arcs[a];
    const mobius::ArcBisector b = mobius::arc_bisector(arc, g.nodes);
    const double s = arc_site_spread(arc, centre, scale, {b.v.real(), b.v.imag()});
    for (int f : {face_of_half[2 * a], face_of_half[2 * a + 1]})
      if (f != kNone) spread[f] = std::min(spread[f], s);
  }
  for (double& s : spread)
    if (!std::isfinite(s)) s = 1.0;
  return spread;
}

namespace stages {

Reconstruction collect_sites(const TracedGraph& t, const LargeVector<FaceSite>& site, const LargeVector<double>& spread,
                             double weight_snap) {
  const double tol = t.tol;
  const int faces = static_cast<int>(site.size());
  // The two orders are independent: one worker each.
  LargeVector<double> weight(faces, 0.0);
  LargeVector<Keyed> by_x;
  if (worker_count(site.size()) > 1) {
    std::thread other([&] { sort_by_x(site, by_x); });
    snap_weights(site, weight_snap, weight);
    other.join();
  } else {
    snap_weights(site, weight_snap, weight);
    sort_by_x(site, by_x);
  }
  LargeVector<int> group = earliest_same_site(by_x, faces, tol);
  for (int f = 0; f < faces; ++f)
    if (group[f] == kNone) group[f] = f;
  join_far_orphans(t, by_x, spread, weight, group);
  double wmax = 0;
  for (int f = 0; f < faces; ++f) wmax = std::max(wmax, weight[f]);
  Reconstruction r;
  r.sites.reserve(by_x.size());  // at most one site per assigned face
  r.face_site.reserve(faces);
  advise_huge_pages(r.sites.data(), r.sites.capacity() * sizeof(Site));
  advise_huge_pages(r.face_site.data(), r.face_site.capacity() * sizeof(int));
  r.face_site.assign(faces, kNone);
  LargeVector<int> placed_by;  // per site, its best-stated face (the earliest of those)
  placed_by.reserve(by_x.size());
  for (int f = 0; f < faces; ++f) {
    if (!site[f].assigned) continue;
    const int first = group_of(group, f);
    if (first != f) {
      const int k = r.face_site[first];
      r.face_site[f] = k;
      if (spread[f] < spread[placed_by[k]]) placed_by[k] = f;
      continue;
    }
    r.face_site[f] = static_cast<int>(placed_by.size());
    placed_by.push_back(f);
  }
  r.sites.resize(placed_by.size());
  parallel_chunks(placed_by.size(), worker_count(placed_by.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t k = b; k < e; ++k) {
      const int f = placed_by[k];
      r.sites[k] = {"s" + std::to_string(k), site[f].position.real(), site[f].position.imag(), weight[f] / wmax};
    }
  });
  return r;
}

}  // namespace stages
}  // namespace covmap::recognition
