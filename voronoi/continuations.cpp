// Continuations for trace_faces(): per half-arc, the half-arc after it around its face, at the node
// where it ends (by site labels, or by angle where a region touches itself or tracing is by
// geometry), or around infinity.
#include <algorithm>
#include <cmath>
#include <map>
#include <span>
#include <vector>

#include "core/parallel.h"
#include "voronoi/arc_path.h"
#include "voronoi/face_tracing.h"

namespace covmap::voronoi::tracing {
namespace {

// Outgoing half-arcs per node in compressed rows (begin[v] .. begin[v+1]), and half-arcs arriving
// from infinity per site.
struct Outgoing {
  LargeVector<int> begin, list;
  std::map<int, std::vector<int>> from_infinity;
  std::span<const int> at(int v) const {
    return std::span<const int>(list.data() + begin[v], begin[v + 1] - begin[v]);
  }
};

Outgoing outgoing_half_arcs(const Diagram& d, bool by_sites) {
  const int halves = 2 * static_cast<int>(d.arcs.size());
  Outgoing o;
  o.begin.assign(d.nodes.size() + 1, 0);
  for (int h = 0; h < halves; ++h) {
    const HalfInfo hi = info(d, h);
    if (label(d, by_sites, h) == kNone) continue;
    if (hi.start == kNone) {
      if (hi.end != kNone || std::holds_alternative<Line>(d.arcs[h / 2].curve))
        o.from_infinity[label(d, by_sites, h)].push_back(h);
    } else {
      ++o.begin[hi.start + 1];
    }
  }
  for (std::size_t v = 0; v < d.nodes.size(); ++v) o.begin[v + 1] += o.begin[v];
  o.list.resize(o.begin.back());
  {
    LargeVector<int> fill(o.begin.begin(), o.begin.end() - 1);
    for (int h = 0; h < halves; ++h) {
      const HalfInfo hi = info(d, h);
      if (label(d, by_sites, h) != kNone && hi.start != kNone) o.list[fill[hi.start]++] = h;
    }
  }
  for (auto& [site, list] : o.from_infinity)
    std::sort(list.begin(), list.end(), [&](int a, int b) {
      return key_less(infinity_key(d, a, false), infinity_key(d, b, false));
    });
  return o;
}

// Two lines leaving one node in directions equal to rounding: the bisectors of nearly collinear
// sites of equal weight, which meet 1e15 extents out, where their directions differ by 1e-18 and
// the node is stated only to ±0.5. Their order there is read near the graph instead, from the
// points the lines are stated through: going from the node along the common direction u, the line
// that passes the other on its left has the larger angle (behind the node, the smaller). +1 when y
// lies counter-clockwise of x, -1 when clockwise, 0 when this cannot tell (not two lines, or the
// same line).
int parallel_lines_side(const Diagram& d, int x, int y) {
  const Line* lx = std::get_if<Line>(&d.arcs[x / 2].curve);
  const Line* ly = std::get_if<Line>(&d.arcs[y / 2].curve);
  if (!lx || !ly) return 0;
  const double sx = x % 2 == 0 ? 1.0 : -1.0;  // the direction of travel of half-arc x
  const Point u{sx * lx->dx, sx * lx->dy};
  const Arc& ax = d.arcs[x / 2];
  const Node& v = d.nodes[x % 2 == 0 ? ax.from : ax.to];
  const double offset = u.x * (ly->y - lx->y) - u.y * (ly->x - lx->x);  // y's point left of x's line: > 0
  const double ahead = u.x * (0.5 * (lx->x + ly->x) - v.x) + u.y * (0.5 * (lx->y + ly->y) - v.y);
  if (offset == 0 || ahead == 0 || !std::isfinite(offset * ahead)) return 0;
  return (offset > 0) == (ahead > 0) ? 1 : -1;
}

// The half-arcs leaving one node in counter-clockwise order. Departures whose pseudo-angles agree
// within tolerance::kParallelAngle (chained: a run of such gaps is one group, so the grouping is
// the same whoever asks) leave in the same direction as far as rounding can tell: of those, the
// one bending more to the left lies at larger angles next to the node, and at equal curvature
// (two lines, or two equal circles) the directions decide, compared by the sign of their cross
// product (the pseudo-angles round away the difference near their wrap). One order per node, from
// which every continuation there is read, makes the continuations a permutation of the half-arcs
// however many departures are tied: choosing pairwise with a tolerance is not transitive (nearly
// parallel lines meeting far away, departures 4e-16 apart at equal curvature, would give two
// half-arcs the same successor and lose their faces).
void counter_clockwise(const Diagram& d, const TracingGeometry& geometry, std::span<const int> out,
                       std::vector<int>& order) {
  order.assign(out.begin(), out.end());
  const auto& dep = geometry.depart;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return dep[a].angle != dep[b].angle ? dep[a].angle < dep[b].angle : a < b;
  });
  const std::size_t n = order.size();
  if (n < 2) return;
  // The gap before position i, cyclically (pseudo-angles lie in [0, kPseudoTurn]; the order is
  // ascending but for one wrap).
  auto gap = [&](std::size_t i) {
    const double g = dep[order[i]].angle - dep[order[(i + n - 1) % n]].angle;
    return g < 0 ? g + kPseudoTurn : g;
  };
  // Start at a clear gap, so that no group straddles the wrap from kPseudoTurn to 0.
  std::size_t cut = 0;
  while (cut < n && gap(cut) <= tolerance::kParallelAngle) ++cut;
  if (cut == n) cut = 0;  // every departure in one direction: one group
  std::rotate(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(cut), order.end());
  auto direction = [&](int h) {
    const Arc& arc = d.arcs[h / 2];
    return departure_vector(arc, d.nodes[h % 2 == 0 ? arc.from : arc.to], h % 2 == 0);
  };
  for (std::size_t b = 0; b < n;) {
    std::size_t e = b + 1;
    while (e < n && gap(e) <= tolerance::kParallelAngle) ++e;
    if (e - b > 1)
      std::sort(order.begin() + static_cast<std::ptrdiff_t>(b), order.begin() + static_cast<std::ptrdiff_t>(e),
                [&](int x, int y) {
                  if (dep[x].curvature != dep[y].curvature) return dep[x].curvature < dep[y].curvature;
                  if (const int side = parallel_lines_side(d, x, y)) return side > 0;
                  const Point u = direction(x), v = direction(y);
                  const double cross = u.x * v.y - u.y * v.x;  // > 0: y lies counter-clockwise of x
                  return cross != 0 ? cross > 0 : x < y;
                });
    b = e;
  }
}

// The continuation of half-arc h at the node where it ends, among the outgoing half-arcs `out`
// there that `eligible` admits: the face is on the left, so it is the first outgoing arc
// clockwise from the reversed incoming direction, the departure of the twin h ^ 1.
template <class Eligible>
int turn_at(const Diagram& d, const TracingGeometry& geometry, std::span<const int> out, int h, Eligible&& eligible) {
  std::vector<int> around(out.begin(), out.end());
  if (std::find(around.begin(), around.end(), h ^ 1) == around.end()) around.push_back(h ^ 1);
  std::vector<int> order;
  counter_clockwise(d, geometry, around, order);
  const std::size_t n = order.size();
  const std::size_t back = std::find(order.begin(), order.end(), h ^ 1) - order.begin();
  for (std::size_t k = 1; k < n; ++k) {
    const int c = order[(back + n - k) % n];
    if (eligible(c)) return c;
  }
  return h ^ 1;  // none: a dangling end, come back along the same arc
}

int next_of(const Diagram& d, bool by_sites, const TracingGeometry& geometry, const Outgoing& outgoing, int h) {
  const HalfInfo hi = info(d, h);
  const Arc& arc = d.arcs[h / 2];
  if (hi.end == kNone) {
    if (hi.start == kNone && std::holds_alternative<Circle>(arc.curve)) return h;  // full circle
    // Around infinity, counter-clockwise, to the next arc of this site coming back.
    const auto found = outgoing.from_infinity.find(label(d, by_sites, h));  // read-only: next_of runs on several threads
    if (found == outgoing.from_infinity.end() || found->second.empty()) return -1;
    const auto& list = found->second;
    const AtInfinity leave = infinity_key(d, h, true);
    for (int c : list)
      if (key_less(leave, infinity_key(d, c, false))) return c;
    return list.front();
  }
  int best = -1;
  int count = 0;
  for (int c : outgoing.at(hi.end))
    if (label(d, by_sites, c) == label(d, by_sites, h)) {
      ++count;
      best = c;
    }
  if (count <= 1) return best;
  return turn_at(d, geometry, outgoing.at(hi.end), h, [&](int c) { return label(d, by_sites, c) == label(d, by_sites, h); });
}

}  // namespace

LargeVector<int> continuations(const Diagram& d, bool by_sites, const TracingGeometry& geometry) {
  const int halves = 2 * static_cast<int>(d.arcs.size());
  const Outgoing outgoing = outgoing_half_arcs(d, by_sites);
  // The continuation of every half-arc, computed once (in parallel; next_of only reads).
  LargeVector<int> next_half(halves, -1);
  if (by_sites) {
    parallel_chunks(static_cast<std::size_t>(halves), worker_count(halves), [&](std::size_t b, std::size_t e, int) {
      for (int h = static_cast<int>(b); h < static_cast<int>(e); ++h)
        if (label(d, by_sites, h) != kNone) next_half[h] = next_of(d, by_sites, geometry, outgoing, h);
    });
    return next_half;
  }
  // By geometry every arc at a node is eligible, so the continuations are settled node by node:
  // each half-arc arriving at v is the twin of one leaving it, and all the data is v's own.
  const std::size_t nodes = d.nodes.size();
  parallel_chunks(nodes, worker_count(nodes), [&](std::size_t b, std::size_t e, int) {
    std::vector<int> order;  // reused from node to node
    for (std::size_t v = b; v < e; ++v) {
      const auto out = outgoing.at(static_cast<int>(v));
      // Each arriving half-arc continues along the departure just clockwise of its twin's.
      counter_clockwise(d, geometry, out, order);
      for (std::size_t k = 0; k < order.size(); ++k)
        next_half[order[k] ^ 1] = order[(k + order.size() - 1) % order.size()];
    }
  });
  parallel_chunks(static_cast<std::size_t>(halves), worker_count(halves), [&](std::size_t b, std::size_t e, int) {
    for (int h = static_cast<int>(b); h < static_cast<int>(e); ++h)
      if (info(d, h).end == kNone) next_half[h] = next_of(d, by_sites, geometry, outgoing, h);
  });
  return next_half;
}

}  // namespace covmap::voronoi::tracing
