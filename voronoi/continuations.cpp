// Continuations for trace_faces(): per half-arc, the half-arc after it around its face, at the node
// where it ends (by site labels, or by angle where a region touches itself or tracing is by
// geometry), or around infinity. By geometry, also the nodes whose combinatorics rounding can change.
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

// The continuation of half-arc h at the node where it ends, among the outgoing half-arcs
// `out` there that `eligible` admits. The region touches this node more than once (or faces are
// traced by geometry): take the first outgoing arc clockwise from the reversed incoming
// direction (the face is on the left); of arcs leaving in the same direction, the one bending
// more to the left lies at larger angles next to the node, so the clockwise sweep from the back
// direction meets it first. The reversed incoming direction is the departure of the twin h ^ 1.
template <class Eligible>
int turn_at(const TracingGeometry& geometry, std::span<const int> out, int h, Eligible&& eligible) {
  const auto& back = geometry.depart[h ^ 1];
  int best = -1;
  double best_angle = 1e9, best_curvature = 0.0;
  for (int c : out) {
    if (c == (h ^ 1) || !eligible(c)) continue;
    const auto& dc = geometry.depart[c];
    // Clockwise turn from the back direction to c's departure, in (0, 4] (both are pseudo-angles
    // in [0, 4), so their difference lies in (-4, 4)).
    double cw = back.angle - dc.angle;
    if (cw <= 0) cw += kPseudoTurn;
    // Leaving along the way we came: right of the returning arc (bending less left) comes first
    // in the sweep, left of it last.
    if (cw < tolerance::kParallelAngle || cw > kPseudoTurn - tolerance::kParallelAngle)
      cw = dc.curvature < back.curvature ? 0.0 : kPseudoTurn;
    if (best < 0 || cw < best_angle - tolerance::kParallelAngle ||
        (cw <= best_angle + tolerance::kParallelAngle && dc.curvature > best_curvature))
      best_angle = cw, best_curvature = dc.curvature, best = c;
  }
  return best < 0 ? h ^ 1 : best;  // none: a dangling end, come back along the same arc
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
  return turn_at(geometry, outgoing.at(hi.end), h, [&](int c) { return label(d, by_sites, c) == label(d, by_sites, h); });
}

// A node whose degree is not three or where two arcs are tangent.
bool degenerate(const TracingGeometry& geometry, std::span<const int> out) {
  bool degenerate = out.size() != 3;
  for (std::size_t i = 0; i < out.size() && !degenerate; ++i)
    for (std::size_t j = i + 1; j < out.size(); ++j) {
      // Tangent curves: directions equal or opposite (pseudo-angles differ by 0, 2 or 4).
      const double diff = std::abs(geometry.depart[out[i]].angle - geometry.depart[out[j]].angle);
      const double off = std::min({diff, std::abs(diff - 0.5 * kPseudoTurn), std::abs(diff - kPseudoTurn)});
      if (off < tolerance::kParallelAngle) degenerate = true;
    }
  return degenerate;
}

}  // namespace

LargeVector<int> continuations(const Diagram& d, bool by_sites, const TracingGeometry& geometry, FaceIndex* index) {
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
  if (index) index->degenerate_node.resize(nodes);
  parallel_chunks(nodes, worker_count(nodes), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t v = b; v < e; ++v) {
      const auto out = outgoing.at(static_cast<int>(v));
      for (int c : out) next_half[c ^ 1] = turn_at(geometry, out, c ^ 1, [](int) { return true; });
      if (!index) continue;
      index->degenerate_node[v] = degenerate(geometry, out);
    }
  });
  parallel_chunks(static_cast<std::size_t>(halves), worker_count(halves), [&](std::size_t b, std::size_t e, int) {
    for (int h = static_cast<int>(b); h < static_cast<int>(e); ++h)
      if (info(d, h).end == kNone) next_half[h] = next_of(d, by_sites, geometry, outgoing, h);
  });
  return next_half;
}

}  // namespace covmap::voronoi::tracing
