// The engine against an independent brute-force oracle on tiny inputs (2..7 sites).
//
// The oracle shares no code with the engine (nor with check/); it works straight from the
// MWVD definition (p belongs to the site minimising |p - s| / w), in long double:
//  1. Nodes: for every triple of sites, intersect two of its bisectors (Apollonius circle, or the
//     perpendicular bisector line for equal weights): 0, 1 (tangent) or 2 points. Keep those where
//     no other site is strictly weighted-closer, merge points that coincide (a node of degree > 3
//     comes from several triples). The engine's nodes must match these one-to-one.
//  2. Arcs: for every pair (i, j), split bisector(i, j) at the reference nodes lying on it and
//     sample each piece to decide whether i and j own it (no third site closer). Every owned piece
//     is one engine arc (a circle without nodes is a full circle, a circle with one node a loop
//     through it, a line piece reaching infinity is a ray, counted on its own).
//  3. Sides: every engine arc lies on its sites' bisector, is owned by them at its midpoint, and has
//     left_site on the left of its direction of travel there (by the sign of the gradient of
//     f_left - f_right along the left normal).
// Pieces are split at every reference node on the bisector, so an arc through a point where a
// third site only touches is two arcs (as the engine's contract has it: arcs run between
// consecutive nodes). Ties are decided with a relative tolerance of 1e-12 (plus 1e-14 * scale);
// when a sample cannot be decided the oracle says so (OracleTrouble) instead of guessing.
// On failure the sites are printed with full precision, ready to paste into a regression test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "core/diagram.h"
#include "voronoi/engine.h"

namespace covmap::voronoi {
namespace {

using R = long double;
constexpr R kPi = 3.141592653589793238462643383279502884L;
constexpr R kTwoPi = 2 * kPi;

// Tolerances (relative to the scale = diagonal of the sites' bounding box, or to the weighted
// distance at the point).
constexpr R kTieRel = 1e-12L;        // f_m within this relative amount of f_i: a tie
constexpr R kTieAbs = 1e-14L;        // ... or within this * scale / max weight (far points)
constexpr R kSpreadRel = 1e-9L;      // a computed triple point must be equidistant to this
constexpr R kMergeRel = 1e-9L;       // reference points closer than this * scale: one node
constexpr R kTangentRel2 = 1e-15L;   // |h^2| below this * scale^2: tangent (one point)
constexpr R kMatchRel = 1e-7L;       // engine node within this * scale of its reference node
constexpr R kEngineCurveRel = 1e-7L; // engine arc midpoint weighted-equidistant to this

struct P2 {
  R x = 0;
  R y = 0;
};
P2 operator+(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
P2 operator-(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }
P2 operator*(P2 a, R k) { return {a.x * k, a.y * k}; }
R dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }
R cross(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
R norm(P2 a) { return std::hypot(a.x, a.y); }
P2 perp(P2 a) { return {-a.y, a.x}; }  // rotated +90 degrees (to the left)

P2 at(const Site& s) { return {static_cast<R>(s.x), static_cast<R>(s.y)}; }
R wdist(const Site& s, P2 p) { return norm(p - at(s)) / static_cast<R>(s.weight); }

// The bisector of two sites: an Apollonius circle, or a line for equal weights.
struct Bisector {
  bool line = false;
  P2 c;      // circle centre
  R r = 0;   // circle radius
  P2 p;      // line: a point on it
  P2 d;      // line: direction, exactly perp(s_j - s_i) (unnormalised, for exact parallelism)
  P2 u;      // line: unit direction
};

Bisector make_bisector(const Site& a, const Site& b) {
  Bisector bis;
  const P2 si = at(a), sj = at(b);
  const R wi = a.weight, wj = b.weight;
  const P2 delta = sj - si;
  if (a.weight == b.weight) {
    bis.line = true;
    bis.p = si + delta * 0.5L;
    bis.d = perp(delta);
    bis.u = bis.d * (1 / norm(bis.d));
  } else {
    // A correction added to s_i, difference of squares factored (docs/NUMERICS.md,
    // 'Apollonius centre').
    const R diff2 = (wi - wj) * (wi + wj);
    bis.c = si + delta * (wi * wi / diff2);
    bis.r = wi * wj * norm(delta) / std::fabs(diff2);
  }
  return bis;
}

// Circle (c1, r1) with circle (c2, r2), computed from the smaller circle's side.
std::vector<P2> meet_circles(P2 c1, R r1, P2 c2, R r2, R tangent_tol2) {
  if (r1 > r2) {
    std::swap(c1, c2);
    std::swap(r1, r2);
  }
  const P2 v = c2 - c1;
  const R dist = norm(v);
  if (dist == 0) return {};
  const P2 u = v * (1 / dist);
  const R a = ((dist - r2) * (dist + r2) + r1 * r1) / (2 * dist);  // along u from c1
  const R h2 = (r1 - a) * (r1 + a);
  const P2 foot = c1 + u * a;
  if (h2 < -tangent_tol2) return {};
  if (h2 <= tangent_tol2) return {foot};
  const R h = std::sqrt(h2);
  return {foot + perp(u) * h, foot - perp(u) * h};
}

std::vector<P2> meet_circle_line(P2 c, R r, const Bisector& line, R tangent_tol2) {
  const R t0 = dot(c - line.p, line.u);
  const P2 foot = line.p + line.u * t0;
  const R e = std::fabs(cross(line.u, c - line.p));
  const R h2 = (r - e) * (r + e);
  if (h2 < -tangent_tol2) return {};
  if (h2 <= tangent_tol2) return {foot};
  const R h = std::sqrt(h2);
  return {foot + line.u * h, foot - line.u * h};
}

std::vector<P2> meet_lines(const Bisector& a, const Bisector& b) {
  const R den = cross(a.d, b.d);
  if (den == 0) return {};  // parallel (bisectors of distinct pairs never coincide)
  const R t = cross(b.p - a.p, b.d) / den;
  return {a.p + a.d * t};
}

std::vector<P2> meet(const Bisector& a, const Bisector& b, R tangent_tol2) {
  if (a.line && b.line) return meet_lines(a, b);
  if (a.line) return meet_circle_line(b.c, b.r, a, tangent_tol2);
  if (b.line) return meet_circle_line(a.c, a.r, b, tangent_tol2);
  return meet_circles(a.c, a.r, b.c, b.r, tangent_tol2);
}

struct RefNode {
  P2 p;
  std::vector<int> tied;  // sites at the minimal weighted distance (within kTieRel)
};

struct Reference {
  int n = 0;
  R scale = 1;
  R tie_abs = 0;  // kTieAbs * scale / max weight
  std::vector<Bisector> bisectors;  // n * n, [i * n + j] for i != j
  std::vector<RefNode> nodes;
  std::vector<std::string> problems;  // the oracle's own consistency failures
  const Bisector& bis(int i, int j) const { return bisectors[i * n + j]; }
};

R bounding_diagonal(const std::vector<Site>& sites) {
  R x0 = sites[0].x, x1 = x0, y0 = sites[0].y, y1 = y0;
  for (const Site& s : sites) {
    x0 = std::min<R>(x0, s.x);
    x1 = std::max<R>(x1, s.x);
    y0 = std::min<R>(y0, s.y);
    y1 = std::max<R>(y1, s.y);
  }
  return std::hypot(x1 - x0, y1 - y0);
}

std::string show(P2 p) {
  std::ostringstream o;
  o << std::setprecision(17) << "(" << static_cast<double>(p.x) << ", " << static_cast<double>(p.y)
    << ")";
  return o.str();
}

Reference build_reference(const std::vector<Site>& sites) {
  Reference ref;
  const int n = static_cast<int>(sites.size());
  ref.n = n;
  ref.scale = bounding_diagonal(sites);
  R wmax = 0;
  for (const Site& s : sites) wmax = std::max<R>(wmax, s.weight);
  ref.tie_abs = kTieAbs * ref.scale / wmax;
  ref.bisectors.resize(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (i != j) ref.bisectors[i * n + j] = make_bisector(sites[i], sites[j]);
  const R tangent_tol2 = kTangentRel2 * ref.scale * ref.scale;
  const R merge_tol = kMergeRel * ref.scale;

  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        for (const P2& p : meet(ref.bis(i, j), ref.bis(i, k), tangent_tol2)) {
          const R fi = wdist(sites[i], p), fj = wdist(sites[j], p), fk = wdist(sites[k], p);
          const R lo = std::min({fi, fj, fk}), hi = std::max({fi, fj, fk});
          if (hi - lo > kSpreadRel * hi) {
            std::ostringstream o;
            o << "oracle: triple (" << i << "," << j << "," << k << ") point " << show(p)
              << " is not weighted-equidistant: spread " << static_cast<double>((hi - lo) / hi);
            ref.problems.push_back(o.str());
          }
          bool beaten = false;
          for (int m = 0; m < n && !beaten; ++m)
            if (m != i && m != j && m != k && wdist(sites[m], p) < lo * (1 - kTieRel) - ref.tie_abs)
              beaten = true;
          if (beaten) continue;
          bool merged = false;
          for (const RefNode& node : ref.nodes)
            if (norm(node.p - p) <= merge_tol) merged = true;
          if (!merged) ref.nodes.push_back({p, {}});
        }
      }
  for (RefNode& node : ref.nodes) {
    R best = std::numeric_limits<R>::infinity();
    for (const Site& s : sites) best = std::min(best, wdist(s, node.p));
    for (int m = 0; m < n; ++m)
      if (wdist(sites[m], node.p) <= best * (1 + kTieRel) + ref.tie_abs) node.tied.push_back(m);
    if (node.tied.size() < 3) {
      ref.problems.push_back("oracle: node " + show(node.p) + " has fewer than 3 tied sites");
    }
  }
  return ref;
}

// +1: q (on bisector(i, j)) is owned by i and j with a clear margin; -1: clearly not; 0: unclear.
int pair_owns(const std::vector<Site>& sites, const Reference& ref, int i, int j, P2 q) {
  const R mine = std::max(wdist(sites[i], q), wdist(sites[j], q));
  R other = std::numeric_limits<R>::infinity();
  for (int m = 0; m < static_cast<int>(sites.size()); ++m)
    if (m != i && m != j) other = std::min(other, wdist(sites[m], q));
  const R tol = kTieRel * mine + ref.tie_abs;
  if (other > mine + tol) return +1;
  if (other < mine - tol) return -1;
  return 0;
}

// Decides ownership of one piece from several sample points; records oracle trouble.
bool piece_owned(const std::vector<Site>& sites, Reference& ref, int i, int j,
                 const std::vector<P2>& samples) {
  std::vector<std::string>& problems = ref.problems;
  int verdict = 0;
  for (const P2& q : samples) {
    const int v = pair_owns(sites, ref, i, j, q);
    if (v == 0) continue;
    if (verdict != 0 && v != verdict) {
      problems.push_back("oracle: piece of bisector(" + std::to_string(i) + "," +
                         std::to_string(j) + ") is owned only in part near " + show(q));
    }
    if (verdict == 0) verdict = v;
  }
  if (verdict == 0) {
    problems.push_back("oracle: ownership of a piece of bisector(" + std::to_string(i) + "," +
                       std::to_string(j) + ") is unclear at every sample");
  }
  return verdict > 0;
}

bool has(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

// Number of maximal owned pieces of bisector(i, j) between consecutive reference nodes.
// `nodes_on` (optional) receives the number of reference nodes on the bisector.
int reference_arc_count(const std::vector<Site>& sites, Reference& ref, int i, int j,
                        int* nodes_on = nullptr) {
  const Bisector& b = ref.bis(i, j);
  std::vector<R> params;
  for (const RefNode& node : ref.nodes) {
    if (!has(node.tied, i) || !has(node.tied, j)) continue;
    if (b.line) {
      params.push_back(dot(node.p - b.p, b.u));
    } else {
      R t = std::atan2(node.p.y - b.c.y, node.p.x - b.c.x);
      if (t < 0) t += kTwoPi;
      params.push_back(t);
    }
  }
  std::sort(params.begin(), params.end());
  const int m = static_cast<int>(params.size());
  if (nodes_on) *nodes_on = m;
  auto on = [&](R t) {
    return b.line ? b.p + b.u * t : b.c + P2{std::cos(t), std::sin(t)} * b.r;
  };
  auto owned_between = [&](R t0, R t1) {
    return piece_owned(sites, ref, i, j,
                       {on(t0 + (t1 - t0) * 0.5L), on(t0 + (t1 - t0) * 0.25L),
                        on(t0 + (t1 - t0) * 0.75L)});
  };
  int count = 0;
  if (!b.line) {
    if (m == 0) {
      std::vector<P2> samples;
      for (int k = 0; k < 16; ++k) samples.push_back(on(0.1L + kTwoPi * k / 16));
      return piece_owned(sites, ref, i, j, samples) ? 1 : 0;
    }
    for (int k = 0; k < m; ++k) {
      const R t0 = params[k];
      const R t1 = k + 1 < m ? params[k + 1] : params[0] + kTwoPi;
      if (owned_between(t0, t1)) ++count;
    }
    return count;
  }
  // Rays: near a far node the margins are tiny (nearly parallel bisectors), so look further out too.
  auto ray = [&](R t0, R sign) {
    std::vector<P2> samples;
    for (R k : {1.0L, 16.0L, 256.0L, 4096.0L}) samples.push_back(on(t0 + sign * k * ref.scale));
    return piece_owned(sites, ref, i, j, samples);
  };
  if (m == 0) return ray(0, +1) ? 1 : 0;
  if (ray(params[0], -1)) ++count;
  for (int k = 0; k + 1 < m; ++k)
    if (owned_between(params[k], params[k + 1])) ++count;
  if (ray(params[m - 1], +1)) ++count;
  return count;
}

std::string dump_sites(const std::vector<Site>& sites) {
  std::ostringstream o;
  o << std::setprecision(17) << "{";
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const Site& s = sites[k];
    o << (k ? ", " : "") << "{\"" << s.id << "\", " << s.x << ", " << s.y << ", " << s.weight
      << "}";
  }
  o << "}";
  return o.str();
}

// The engine arc's midpoint and direction of travel there; false (with a problem) if malformed.
bool arc_midpoint(const Diagram& d, const Arc& a, R scale, P2& q, P2& tangent,
                  std::vector<std::string>& errs, const std::string& name) {
  const int nn = static_cast<int>(d.nodes.size());
  for (int end : {a.from, a.to}) {
    if (end != kNone && (end < 0 || end >= nn)) {
      errs.push_back(name + ": node index out of range");
      return false;
    }
  }
  auto node = [&](int k) { return P2{d.nodes[k].x, d.nodes[k].y}; };
  if (const Circle* c = std::get_if<Circle>(&a.curve)) {
    const P2 centre{c->cx, c->cy};
    const R r = c->r;
    R theta = 0;
    if (a.from == kNone || a.to == kNone) {
      if (a.from != a.to) {
        errs.push_back(name + ": circle arc with exactly one kNone end");
        return false;
      }
    } else {
      const P2 pa = node(a.from) - centre, pb = node(a.to) - centre;
      for (const P2& v : {pa, pb}) {
        if (std::fabs(norm(v) - r) > kMatchRel * scale) {
          errs.push_back(name + ": an end node is off the arc's circle");
        }
      }
      const R ta = std::atan2(pa.y, pa.x), tb = std::atan2(pb.y, pb.x);
      R sweep = a.ccw ? tb - ta : ta - tb;
      while (sweep <= 0) sweep += kTwoPi;
      while (sweep > kTwoPi) sweep -= kTwoPi;
      if (a.from == a.to) sweep = kTwoPi;
      theta = a.ccw ? ta + sweep / 2 : ta - sweep / 2;
    }
    q = centre + P2{std::cos(theta), std::sin(theta)} * r;
    tangent = P2{-std::sin(theta), std::cos(theta)} * (a.ccw ? 1 : -1);
    return true;
  }
  const Line& l = std::get<Line>(a.curve);
  const P2 dir{l.dx, l.dy};
  if (norm(dir) == 0) {
    errs.push_back(name + ": line with zero direction");
    return false;
  }
  const P2 u = dir * (1 / norm(dir));
  const P2 base{l.x, l.y};
  for (int end : {a.from, a.to}) {
    if (end != kNone && std::fabs(cross(u, node(end) - base)) > kMatchRel * scale) {
      errs.push_back(name + ": an end node is off the arc's line");
    }
  }
  if (a.from != kNone && a.to != kNone) {
    if (a.from == a.to || dot(node(a.to) - node(a.from), u) <= 0) {
      errs.push_back(name + ": line arc does not run along +d from 'from' to 'to'");
      return false;
    }
    q = (node(a.from) + node(a.to)) * 0.5L;
  } else if (a.from != kNone) {
    q = node(a.from) + u * scale;
  } else if (a.to != kNone) {
    q = node(a.to) - u * scale;
  } else {
    q = base;
  }
  tangent = u;
  return true;
}

// Position and sides of one engine arc (sites already validated): its midpoint lies on its
// sites' bisector, no other site is closer there, and left_site is on the left of the direction of
// travel. Returns what is wrong.
std::vector<std::string> check_arc(const std::vector<Site>& sites, const Diagram& d, const Arc& a,
                                   R scale, const std::string& name) {
  std::vector<std::string> wrong;
  const int n = static_cast<int>(sites.size());
  const bool line = std::holds_alternative<Line>(a.curve);
  if (line != (sites[a.left_site].weight == sites[a.right_site].weight)) {
    wrong.push_back(name + ": curve kind does not match the sites' weights");
  }
  P2 q, tangent;
  if (!arc_midpoint(d, a, scale, q, tangent, wrong, name)) return wrong;
  const Site& sl = sites[a.left_site];
  const Site& sr = sites[a.right_site];
  const R fl = wdist(sl, q), fr = wdist(sr, q);
  std::ostringstream o;
  o << name << " (" << a.left_site << " left, " << a.right_site << " right) midpoint " << show(q);
  if (std::fabs(fl - fr) > kEngineCurveRel * std::max(fl, fr)) {
    wrong.push_back(o.str() + " is not on the sites' bisector");
    return wrong;
  }
  R other = std::numeric_limits<R>::infinity();
  int other_site = kNone;
  for (int m = 0; m < n; ++m) {
    if (m == a.left_site || m == a.right_site) continue;
    const R f = wdist(sites[m], q);
    if (f < other) {
      other = f;
      other_site = m;
    }
  }
  if (other < std::max(fl, fr) * (1 - kEngineCurveRel)) {
    wrong.push_back(o.str() + " is owned by site " + std::to_string(other_site));
    return wrong;
  }
  const P2 gl = (q - at(sl)) * (1 / (norm(q - at(sl)) * sl.weight));
  const P2 gr = (q - at(sr)) * (1 / (norm(q - at(sr)) * sr.weight));
  const P2 g = gl - gr;  // f_left - f_right grows along g: towards the right site's side
  const R along_left = dot(g, perp(tangent));
  if (!(along_left < -0.5L * norm(g))) {
    wrong.push_back(o.str() + (along_left > 0 ? ": left and right sites are swapped"
                                              : ": direction of travel is not along the curve"));
  }
  return wrong;
}

// What one comparison found. Every finding is a failure; the kinds only label the findings (the
// shapes in which the engine bugs found so far showed up, see the EngineBug* tests at the end).
enum class Kind {
  Disagreement,    // the engine and the oracle differ
  Missing,         // a reference node, or a reference arc of a pair, that the engine lacks
  NodeAtInfinity,  // a node with non-finite coordinates (an unbounded end must be kNone)
  SplitNode,       // a node of degree > 3 reported as several coincident nodes
  DegenerateArc,   // an arc from a node of degree > 3 to itself (or to a coincident copy)
  OracleTrouble,   // the oracle could not decide (its own consistency checks failed)
};

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::Disagreement: return "disagreement";
    case Kind::Missing: return "missing in the engine";
    case Kind::NodeAtInfinity: return "node at infinity";
    case Kind::SplitNode: return "node of degree > 3 split";
    case Kind::DegenerateArc: return "arc from a node of degree > 3 to itself";
    case Kind::OracleTrouble: return "oracle trouble";
  }
  return "?";
}

struct Finding {
  Kind kind;
  std::string text;
};

// Compares the engine with the oracle; empty: full agreement.
std::vector<Finding> compare_with_reference(const std::vector<Site>& sites) {
  std::vector<Finding> out;
  auto add = [&](Kind kind, const std::string& text) { out.push_back({kind, text}); };
  Diagram d;
  try {
    d = build_diagram(sites);
  } catch (const std::exception& e) {
    add(Kind::Disagreement, std::string("engine threw: ") + e.what());
    return out;
  }
  Reference ref = build_reference(sites);
  const int n = static_cast<int>(sites.size());
  const R tol = kMatchRel * ref.scale;
  const int en = static_cast<int>(d.nodes.size());

  // 0. Every node is a finite point (unbounded ends are kNone, not nodes at infinity). Arcs ending
  // at a non-finite node are then read as ending at infinity, so the rest of the comparison runs.
  std::vector<bool> infinite_node(en, false);
  for (int e = 0; e < en; ++e) {
    if (std::isfinite(d.nodes[e].x) && std::isfinite(d.nodes[e].y)) continue;
    infinite_node[e] = true;
    std::ostringstream o;
    o << "engine node " << e << " has non-finite coordinates " << show({d.nodes[e].x, d.nodes[e].y});
    add(Kind::NodeAtInfinity, o.str());
  }
  for (Arc& a : d.arcs)
    for (int* end : {&a.from, &a.to})
      if (*end >= 0 && *end < en && infinite_node[*end]) *end = kNone;

  // 1. Nodes, one-to-one.
  std::vector<std::vector<int>> engine_to_ref(en), ref_to_engine(ref.nodes.size());
  for (int e = 0; e < en; ++e) {
    if (infinite_node[e]) continue;
    const P2 p{d.nodes[e].x, d.nodes[e].y};
    for (std::size_t r = 0; r < ref.nodes.size(); ++r)
      if (norm(ref.nodes[r].p - p) <= tol) {
        engine_to_ref[e].push_back(static_cast<int>(r));
        ref_to_engine[r].push_back(e);
      }
  }
  for (int e = 0; e < en; ++e) {
    if (infinite_node[e] || engine_to_ref[e].size() == 1) continue;
    const P2 p{d.nodes[e].x, d.nodes[e].y};
    R nearest = std::numeric_limits<R>::infinity();
    for (const RefNode& r : ref.nodes) nearest = std::min(nearest, norm(r.p - p));
    std::ostringstream o;
    o << "engine node " << e << " " << show(p) << " matches " << engine_to_ref[e].size()
      << " reference nodes (nearest at " << static_cast<double>(nearest / ref.scale)
      << " * scale)";
    add(Kind::Disagreement, o.str());
  }
  for (std::size_t r = 0; r < ref.nodes.size(); ++r) {
    const std::vector<int>& hits = ref_to_engine[r];
    if (hits.size() == 1) continue;
    std::ostringstream o;
    o << "reference node " << show(ref.nodes[r].p) << " (tied sites";
    for (int t : ref.nodes[r].tied) o << " " << t;
    o << ") matches " << hits.size() << " engine nodes";
    for (int e : hits) o << " " << e;
    const bool split = hits.size() >= 2 && ref.nodes[r].tied.size() >= 4 &&
                       std::all_of(hits.begin(), hits.end(),
                                   [&](int e) { return engine_to_ref[e].size() == 1; });
    add(split ? Kind::SplitNode : hits.empty() ? Kind::Missing : Kind::Disagreement, o.str());
  }

  // 2 and 3. Arcs: per-pair counts (below) and, arc by arc, position and sides.
  std::vector<int> engine_count(n * n, 0);
  for (std::size_t k = 0; k < d.arcs.size(); ++k) {
    const Arc& a = d.arcs[k];
    const std::string name = "engine arc " + std::to_string(k);
    if (a.frame) {
      add(Kind::Disagreement, name + " is a frame arc in an unclipped diagram");
      continue;
    }
    if (a.left_site < 0 || a.left_site >= n || a.right_site < 0 || a.right_site >= n ||
        a.left_site == a.right_site) {
      add(Kind::Disagreement, name + " has bad sites " + std::to_string(a.left_site) + "/" +
                                  std::to_string(a.right_site));
      continue;
    }
    const bool ends_ok = (a.from == kNone || (a.from >= 0 && a.from < en)) &&
                         (a.to == kNone || (a.to >= 0 && a.to < en));
    if (!ends_ok) {
      add(Kind::Disagreement, name + " has a node index out of range");
      continue;
    }
    // Bug B: an arc whose two ends are one node of degree > 3 (or coincident copies of it).
    auto ref_of = [&](int e) {
      return e >= 0 && engine_to_ref[e].size() == 1 ? engine_to_ref[e][0] : -1;
    };
    const int rf = ref_of(a.from);
    const bool line = std::holds_alternative<Line>(a.curve);
    const bool at_high_degree_node =
        rf >= 0 && rf == ref_of(a.to) && ref.nodes[rf].tied.size() >= 4;
    std::ostringstream deg;
    deg << name << " (sites " << a.left_site << "," << a.right_site << ", "
        << (line ? "line" : "circle") << ") runs from node " << a.from << " to node " << a.to
        << ", both the degree-" << (at_high_degree_node ? ref.nodes[rf].tied.size() : 0)
        << " node " << (at_high_degree_node ? show(ref.nodes[rf].p) : "");
    if (at_high_degree_node && (line || a.from != a.to)) {
      add(Kind::DegenerateArc, deg.str());
      continue;  // neither counted nor side-checked
    }
    const std::vector<std::string> wrong = check_arc(sites, d, a, ref.scale, name);
    if (at_high_degree_node && !wrong.empty()) {
      add(Kind::DegenerateArc, deg.str() + ", and its loop is wrong: " + wrong.front());
      continue;
    }
    for (const std::string& w : wrong) add(Kind::Disagreement, w);
    const int i = std::min(a.left_site, a.right_site), j = std::max(a.left_site, a.right_site);
    ++engine_count[i * n + j];
  }
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      int nodes_on = 0;
      const int want = reference_arc_count(sites, ref, i, j, &nodes_on);
      const int have = engine_count[i * n + j];
      if (want == have) continue;
      add(have < want ? Kind::Missing : Kind::Disagreement,
          "pair (" + std::to_string(i) + "," + std::to_string(j) + "): engine has " +
              std::to_string(have) + " arcs, reference " + std::to_string(want) +
              (nodes_on == 0 ? " (no reference node on the bisector)" : ""));
    }
  for (const std::string& p : ref.problems) add(Kind::OracleTrouble, p);
  return out;
}

std::string report(const std::vector<Site>& sites, const std::vector<Finding>& findings) {
  std::ostringstream o;
  o << "sites = " << dump_sites(sites) << "\n";
  for (const Finding& f : findings) o << "  [" << kind_name(f.kind) << "] " << f.text << "\n";
  return o.str();
}

// Runs a batch; fails on any finding, printing the first few instances in full.
template <class Make>
void run_batch(const char* label, int count, Make make) {
  int failures = 0;
  std::ostringstream details;
  for (int k = 0; k < count; ++k) {
    const std::vector<Site> sites = make(k);
    const std::vector<Finding> findings = compare_with_reference(sites);
    if (findings.empty()) continue;
    if (++failures <= 5) details << label << " instance " << k << ":\n" << report(sites, findings);
  }
  EXPECT_EQ(failures, 0) << failures << " of " << count << " " << label
                         << " instances disagree with the brute force; first ones:\n"
                         << details.str();
}

std::vector<Site> with_ids(std::vector<Site> sites) {
  for (std::size_t k = 0; k < sites.size(); ++k) sites[k].id = std::to_string(k);
  return sites;
}

// Hand cases: any finding fails.
void expect_agreement(const std::vector<Site>& sites) {
  const std::vector<Finding> findings = compare_with_reference(sites);
  EXPECT_TRUE(findings.empty()) << report(sites, findings);
}

TEST(BruteForceReference, RandomUniformWeights) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> weight(1.0, 3.0);
  std::uniform_int_distribution<int> size(2, 7);
  run_batch("uniform-weights", 2000, [&](int) {
    std::vector<Site> sites(size(rng));
    for (Site& s : sites) {
      s.x = unit(rng);
      s.y = unit(rng);
      s.weight = weight(rng);
    }
    return with_ids(sites);
  });
}

TEST(BruteForceReference, RandomWeightsOneOrTwo) {
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> size(2, 7), weight(1, 2);
  run_batch("weights-1-2", 500, [&](int) {
    std::vector<Site> sites(size(rng));
    for (Site& s : sites) {
      s.x = unit(rng);
      s.y = unit(rng);
      s.weight = weight(rng);
    }
    return with_ids(sites);
  });
}

TEST(BruteForceReference, SmallIntegerGrid) {
  std::mt19937_64 rng(4242);
  std::uniform_int_distribution<int> size(2, 7), coord(0, 3), weight(1, 3);
  run_batch("grid", 300, [&](int) {
    const int n = size(rng);
    std::vector<Site> sites;
    while (static_cast<int>(sites.size()) < n) {
      const double x = coord(rng), y = coord(rng);
      bool taken = false;
      for (const Site& s : sites) taken = taken || (s.x == x && s.y == y);
      if (!taken) sites.push_back({"", x, y, static_cast<double>(weight(rng))});
    }
    return with_ids(sites);
  });
}

TEST(BruteForceReference, CollinearEqualWeightsGiveTwoParallelLines) {
  const std::vector<Site> sites = {{"a", 0, 0, 1}, {"b", 1, 0, 1}, {"c", 2, 0, 1}};
  expect_agreement(sites);
  const Reference ref = build_reference(sites);
  EXPECT_TRUE(ref.nodes.empty());
  const Diagram d = build_diagram(sites);
  EXPECT_TRUE(d.nodes.empty());
  EXPECT_EQ(d.arcs.size(), 2u);
}

TEST(BruteForceReference, SquareGivesOneDegreeFourNode) {
  const std::vector<Site> sites = {{"a", 0, 0, 1}, {"b", 1, 0, 1}, {"c", 1, 1, 1}, {"d", 0, 1, 1}};
  expect_agreement(sites);
  const Reference ref = build_reference(sites);
  ASSERT_EQ(ref.nodes.size(), 1u);
  EXPECT_EQ(ref.nodes[0].tied.size(), 4u);
  const Diagram d = build_diagram(sites);
  EXPECT_EQ(d.nodes.size(), 1u);
  EXPECT_EQ(d.arcs.size(), 4u);
}

TEST(BruteForceReference, FiveWeightedCocircularSites) {
  // Every site is at distance = weight from the origin: a node of degree five there.
  const std::vector<Site> sites = {
      {"a", 1, 0, 1}, {"b", 0, 2, 2}, {"c", -3, 0, 3}, {"d", 0, -4, 4}, {"e", 3, 4, 5}};
  expect_agreement(sites);
  const Reference ref = build_reference(sites);
  int at_origin = 0;
  for (const RefNode& node : ref.nodes) {
    if (norm(node.p) < 1e-9L) {
      ++at_origin;
      EXPECT_EQ(node.tied.size(), 5u);
    }
  }
  EXPECT_EQ(at_origin, 1);
}

// Fixed engine bug A (seen at fefdb23, fixed by 357fe25). Two sites sharing the maximal weight
// have a bisector line reaching infinity at both ends; the engine made the point at infinity
// where both rays end a real node with non-finite coordinates, and when the line had no finite
// node it dropped the whole line. Here sites 0 and 1 own the whole line x = 0.5.
TEST(BruteForceReference, FixedBugWholeLineOfMaximalWeights) {
  const std::vector<Site> sites = {{"0", 0, 0, 2}, {"1", 1, 0, 2}, {"2", 3, 1, 1}, {"3", 3, -1, 1}};
  expect_agreement(sites);
}

// Fixed engine bug A with finite nodes on the line: the two rays of the weight-2 pair (1, 2) on
// y = 1.5 ended at a node (-inf, nan) instead of at kNone.
TEST(BruteForceReference, FixedBugRaysOfMaximalWeightsEndAtInfinity) {
  const std::vector<Site> sites = {{"0", 2, 2, 1}, {"1", 0, 3, 2}, {"2", 0, 0, 2}, {"3", 0, 1, 1}};
  expect_agreement(sites);
}

// Fixed engine bug A, from the random {1, 2} batch.
TEST(BruteForceReference, FixedBugWholeLineOfMaximalWeightsRandom) {
  const std::vector<Site> sites = {{"0", 0.39644829573614698, 0.57138759197797861, 2},
                                   {"1", 0.47348204145672773, 0.88342387976051129, 2},
                                   {"2", 0.2262600473558336, 0.97681593725813576, 1},
                                   {"3", 0.40753132002170389, 0.9476288214127665, 1}};
  expect_agreement(sites);
}

// Fixed engine bug B (seen at fefdb23, fixed by 357fe25). (1.5, 1.5) is equidistant from the four
// weight-3 sites 0..3 (cocircular) and nobody is closer: one node of degree 4 (the four sites
// alone were fine; site 4 triggered it). The engine reported two nodes at exactly (1.5, 1.5)
// joined by a zero-length line arc of the pair (2, 3).
TEST(BruteForceReference, FixedBugDegreeFourNodeSplit) {
  const std::vector<Site> sites = {
      {"0", 0, 1, 3}, {"1", 3, 1, 3}, {"2", 0, 2, 3}, {"3", 2, 0, 3}, {"4", 2, 3, 2}};
  expect_agreement(sites);
}

// Fixed engine bug B with circles: (2, -3.7817...) is weighted-equidistant from sites 0, 1, 2, 5
// (weights 2, 3, 3, 2); the engine reported it twice, joined by an arc of the Apollonius circle of
// (5, 2).
TEST(BruteForceReference, FixedBugDegreeFourNodeOnCirclesSplit) {
  const std::vector<Site> sites = {{"0", 3, 0, 2}, {"1", 1, 2, 3}, {"2", 3, 2, 3},
                                   {"3", 2, 0, 1}, {"4", 3, 1, 2}, {"5", 1, 0, 2}};
  expect_agreement(sites);
}

// Fixed bug C (a regression of 357fe25): colliding hash buckets in the shared-power-line node merge
// let the two crossings of one power line merge into one node. The two weight-1 sites 0
// and 1 share a bounded lens-shaped pair of regions with site 2: reference nodes
// ±(0.8164965809277260, 0.8164965809277260) (tied 0, 1, 2), one segment of (0, 1) on y = x between
// them and one arc each of (0, 2) and (1, 2). The engine reports none of them (only the circle of
// (2, 3)): sites 0 and 1 have no boundary at all.
TEST(BruteForceReference, FixedBugLensOfTwoLightSitesMissing) {
  const std::vector<Site> sites = {{"0", 1, 0, 1}, {"1", 0, 1, 1}, {"2", 2, 2, 2}, {"3", 3, 2, 1}};
  expect_agreement(sites);
}

// Fixed bug C, second shape: site 1 (weight 1) has a bounded region between the weight-2
// sites 2 and 3, with nodes (1, 1) and (-1, -1) (tied 1, 2, 3); the engine drops both nodes and the
// arcs of (1, 2), (1, 3) and one of the two arcs of (2, 3) (the segment between them on y = x).
TEST(BruteForceReference, FixedBugBoundedRegionOfLightSiteMissing) {
  const std::vector<Site> sites = {{"0", 3, 3, 2}, {"1", 0, 1, 1}, {"2", 1, 3, 2}, {"3", 3, 1, 2}};
  expect_agreement(sites);
}

// Fixed bug C as found in the grid batch (instance 140).
TEST(BruteForceReference, FixedBugGridInstance140) {
  const std::vector<Site> sites = {{"0", 1, 3, 1}, {"1", 3, 3, 1}, {"2", 2, 3, 2}, {"3", 1, 0, 1},
                                   {"4", 0, 1, 1}, {"5", 2, 2, 2}, {"6", 3, 2, 1}};
  expect_agreement(sites);
}

}  // namespace
}  // namespace covmap::voronoi
