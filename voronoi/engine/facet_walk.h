// Pieces shared by the 3D and planar extractors: turning the walk around one power facet into
// arcs (nodes are placed by engine/triple_node.h).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "core/diagram.h"
#include "voronoi/engine/power_geometry.h"

namespace covmap::voronoi::engine {

inline constexpr int kInfinityNode = -2;  // the zero point U at infinity (an unbounded arc end)

// The boundary of a power facet as a cyclic token list: a zero point (node id, kInfinityNode for
// U) or the sign of g on a stretch (node == kNone).
struct Token {
  int node = kNone;
  int sign = 0;
};

struct WalkScratch {
  std::vector<int> zeros;
  std::vector<int> after;
  std::vector<int> sorted;
};

// One walked power facet: the boundary tokens, walked counter-clockwise around c_j - c_i, of the
// facet of the site pair (si, sj), whose (x, y, weight) are pi and pj. Views only, made at the call.
struct WalkedFacet {
  const std::vector<Token>& tokens;
  int si = kNone, sj = kNone;
  const RawPoint& pi;
  const RawPoint& pj;
};

// Appends the arcs of the facet's site pair. `full_inside` is consulted only when the walk has no
// zero point and lies outside D: it must say whether the whole bisector lies inside the facet.
// `Arcs` is a vector of Arc (any allocator).
template <class Arcs, class FullInside>
void emit_arcs(const WalkedFacet& facet, WalkScratch& scratch, Arcs& arcs, FullInside&& full_inside);

// The arc of (si, sj), whose (x, y, weight) are pi and pj, from node `from` to node `to` (kNone /
// kInfinityNode at infinity). The extractors pass the triangulation's copies of the sites' values
// (the same doubles as the sites'), which the walks read anyway: the sites themselves, 88 bytes
// each in input order, cost a cache miss per arc at 10^6 sites.
Arc make_arc(int si, int sj, int from, int to, const RawPoint& pi, const RawPoint& pj);
inline Arc make_arc(int si, int sj, int from, int to, const std::vector<Site>& sites) {
  return make_arc(si, sj, from, to, RawPoint(sites[si].x, sites[si].y, sites[si].weight),
                  RawPoint(sites[sj].x, sites[sj].y, sites[sj].weight));
}

// The lift of the Apollonius circle's centre of (pi, pj) is inside D; is it in the facet, i.e. is
// the power to pi no larger than to any site of `link`? Exact.
bool circle_centre_in_facet(const RawPoint& pi, const RawPoint& pj,
                            const std::vector<RawPoint>& link);

template <class Arcs, class FullInside>
void emit_arcs(const WalkedFacet& facet, WalkScratch& scratch, Arcs& arcs, FullInside&& full_inside) {
  const std::vector<Token>& tokens = facet.tokens;
  const int si = facet.si, sj = facet.sj;
  const RawPoint& pi = facet.pi;
  const RawPoint& pj = facet.pj;
  std::vector<int>& zeros = scratch.zeros;
  std::vector<int>& after = scratch.after;
  zeros.clear();
  after.clear();
  int any_sign = 0;
  const std::size_t t = tokens.size();
  for (std::size_t k = 0; k < t; ++k) {
    if (tokens[k].node == kNone) {
      if (tokens[k].sign != 0) any_sign = tokens[k].sign;
      continue;
    }
    // The sign of the stretch that follows; a zero repeated with no stretch between (cells
    // sharing one power vertex) is one point.
    int s = 0;
    bool duplicate = false;
    for (std::size_t q = 1; q < t; ++q) {
      const Token& nx = tokens[(k + q) % t];
      if (nx.node == kNone) {
        if (nx.sign != 0) {
          s = nx.sign;
          break;
        }
        continue;
      }
      duplicate = nx.node == tokens[k].node;
      break;
    }
    if (duplicate) continue;
    zeros.push_back(tokens[k].node);
    after.push_back(s);
  }
  if (zeros.empty()) {
    if (any_sign < 0 && full_inside()) arcs.push_back(make_arc(si, sj, kNone, kNone, pi, pj));
    return;
  }
  // A flat facet (its lifted sites coplanar and co-circular with a neighbour's) is walked along
  // both sides of one segment, so its zero points come twice. ∂D meets it in isolated points only:
  // no arc. (A proper convex facet meets ∂D in distinct points.)
  if (zeros.size() > 1) {
    scratch.sorted.assign(zeros.begin(), zeros.end());
    std::sort(scratch.sorted.begin(), scratch.sorted.end());
    if (std::adjacent_find(scratch.sorted.begin(), scratch.sorted.end()) != scratch.sorted.end())
      return;
  }
  if (zeros.size() == 1) {
    // One touching point. The stretch-rule needs D ∩ Q to have an interior, which fails exactly
    // here: ∂Q may touch ∂D from outside (D ∩ Q is that point: no arc) or from inside (the whole
    // conic is in Q: a loop through the point). U is always touched from inside (Q contains the
    // far-up part of D). For a finite point the circle's centre decides; a line's D is unbounded,
    // so it cannot lie in Q without reaching U.
    if (after[0] >= 0) return;
    if (zeros[0] == kInfinityNode)
      arcs.push_back(make_arc(si, sj, kInfinityNode, kInfinityNode, pi, pj));
    else if (pi.z() != pj.z() && full_inside())  // unequal weights
      arcs.push_back(make_arc(si, sj, zeros[0], zeros[0], pi, pj));
    return;
  }
  for (std::size_t k = 0; k < zeros.size(); ++k) {
    // A stretch of ∂Q inside D (sign > 0) means the matching piece of ∂D is outside Q.
    if (after[k] >= 0) continue;
    arcs.push_back(make_arc(si, sj, zeros[k], zeros[(k + 1) % zeros.size()], pi, pj));
  }
}

}  // namespace covmap::voronoi::engine
