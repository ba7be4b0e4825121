#include "voronoi/engine/readable_arcs.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "voronoi/engine.h"
#include "voronoi/engine/self_check.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi::engine {

namespace {

bool within_rounding(const Node& p, const Node& q, double extent) {
  const double magnitude = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(q.x), std::fabs(q.y)});
  return std::hypot(q.x - p.x, q.y - p.y) <= allowed_off(extent, magnitude);
}

// How a reader takes a circle arc's sweep: the turn from its first node to its last in the arc's
// sense, in [0, 2π).
double read_turn(const Circle& c, bool ccw, const Node& p, const Node& q) {
  const double sense = ccw ? 1.0 : -1.0;
  double turn = std::remainder(sense * (std::atan2(q.y - c.cy, q.x - c.cx) - std::atan2(p.y - c.cy, p.x - c.cx)),
                               2 * M_PI);
  if (turn < 0) turn += 2 * M_PI;
  return turn;
}

}  // namespace

bool ends_within_rounding(const Arc& a, const std::vector<Node>& nodes, const std::vector<Site>& sites,
                          double extent) {
  if (a.from < 0 || a.to < 0 || a.from == a.to) return false;
  // The nodes first: they are rarely within rounding, and the sites, read by index, are far apart
  // in memory (a cache miss per arc at 10^6 sites).
  if (!within_rounding(nodes[a.from], nodes[a.to], extent)) return false;
  const Circle* c = std::get_if<Circle>(&a.curve);
  if (!c) return true;
  const Site& si = sites[a.left_site];
  const Site& sj = sites[a.right_site];
  // Huge circles (nearly equal weights) are read as straight where it matters (kHugeCircleRatio).
  return !(c->r > tolerance::kHugeCircleRatio * std::hypot(sj.x - si.x, sj.y - si.y));
}

ArcMend arc_mend(const Arc& a, const std::vector<Node>& nodes, const std::vector<Site>& sites,
                 const std::vector<int>& zeros, const std::vector<RawPoint>& link, double extent) {
  const Site& si = sites[a.left_site];
  const Site& sj = sites[a.right_site];
  const Node& p = nodes[a.from];
  const Node& q = nodes[a.to];
  const Circle* c = std::get_if<Circle>(&a.curve);
  if (!c) {
    // A segment is always the short piece; it reads wrongly when its rounded nodes run against its
    // direction (equal nodes read as the empty segment it nearly is).
    const Line& l = std::get<Line>(a.curve);
    return (q.x - p.x) * l.dx + (q.y - p.y) * l.dy >= 0 ? ArcMend::kNone : ArcMend::kDrop;
  }
  // Which piece: tiny if some crossing of the circle lies away from the ends; else the point
  // opposite p is on the arc iff no link site is nearer there.
  const bool clustered = std::all_of(zeros.begin(), zeros.end(), [&](int z) { return z >= 0 && within_rounding(nodes[z], p, extent); });
  const double ox = 2 * c->cx - p.x, oy = 2 * c->cy - p.y;
  auto distance = [&](double x, double y, double w) { return std::hypot(ox - x, oy - y) / w; };
  const double own = std::min(distance(si.x, si.y, si.weight), distance(sj.x, sj.y, sj.weight));
  double other = HUGE_VAL;
  for (const RawPoint& l : link) other = std::min(other, distance(l.x(), l.y(), l.z()));
  bool near_full;
  if (!clustered)
    near_full = false;
  else if (other > own * (1 + tolerance::kPieceProbeMargin))
    near_full = true;
  else if (other < own * (1 - tolerance::kPieceProbeMargin))
    near_full = false;
  else
    return ArcMend::kUnknown;
  // How a reader takes the sweep, a zero turn read as full.
  const double turn = read_turn(*c, a.ccw, p, q);
  const bool reads_full = turn == 0 || turn > M_PI;
  if (near_full == reads_full && turn != 0) return ArcMend::kNone;
  return near_full ? ArcMend::kLoop : ArcMend::kDrop;
}

void apply_mends(Diagram& d, const std::vector<ArcMend>& mends) {
  std::vector<int> parent(d.nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  bool any = false;
  for (std::size_t k = 0; k < d.arcs.size(); ++k) {
    if (mends[k] == ArcMend::kNone) continue;
    const Arc& a = d.arcs[k];
    if (mends[k] == ArcMend::kUnknown)
      throw EngineFailure("the engine cannot tell whether the arc of sites '" + d.sites[a.left_site].id + "' and '" +
                          d.sites[a.right_site].id +
                          "', whose end nodes round to one point, is tiny or almost its whole circle");
    parent[find(a.from)] = find(a.to);
    any = true;
  }
  if (!any) return;
  auto near_full = [&](const Arc& a) {
    const Circle* c = std::get_if<Circle>(&a.curve);
    return c && read_turn(*c, a.ccw, d.nodes[a.from], d.nodes[a.to]) > M_PI;
  };
  // A short arc not mended itself, between nodes within rounding, one or both of which others'
  // mends merged into nodes a few ulps away, would be read from those: its two ends can then have
  // one angle in doubles and its sweep be unreadable (a grid's sites an ulp off the integers: the
  // self-check refused the diagram). It is as tiny as the mends it sits between: its ends' nodes are
  // merged too, and it is dropped below. Until no such arc is left (merges cascade in a cluster).
  const double extent = site_extent(d.sites);
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t k = 0; k < d.arcs.size(); ++k) {
      const Arc& a = d.arcs[k];
      if (mends[k] != ArcMend::kNone || a.from == kNone || a.to == kNone || a.from == a.to) continue;
      const int rf = find(a.from), rt = find(a.to);
      if (rf == rt || (rf == a.from && rt == a.to) || near_full(a)) continue;
      if (!within_rounding(d.nodes[a.from], d.nodes[a.to], extent)) continue;
      parent[rf] = rt;
      merged = true;
    }
  }
  // An arc not mended itself whose ends were merged through others' mends has ends farther apart
  // than rounding, or is one of the short arcs just merged, so it reads correctly from them: a
  // near-full one is kept as a loop, a short one (rounding-sized, or a line segment) dropped.
  std::vector<Arc> kept;
  kept.reserve(d.arcs.size());
  for (std::size_t k = 0; k < d.arcs.size(); ++k) {
    Arc a = d.arcs[k];
    const bool loop = a.from == a.to;
    const bool keep_as_loop = mends[k] == ArcMend::kLoop || (mends[k] == ArcMend::kNone && !loop && a.from != kNone &&
                                                             a.to != kNone && near_full(a));
    if (a.from != kNone) a.from = find(a.from);
    if (a.to != kNone) a.to = find(a.to);
    if (a.from != kNone && a.from == a.to && !loop && !keep_as_loop) continue;
    kept.push_back(a);
  }
  d.arcs.swap(kept);
}

}  // namespace covmap::voronoi::engine
