#include "voronoi/faces.h"

#include "core/parallel.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <unordered_map>

#include "voronoi/arc_path.h"
#include "voronoi/box_grid.h"
#include "core/extent.h"
#include "core/large_buffer.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;
// Direction of the containment test ray: any angle works; an irrational-looking one avoids rays
// along the axes, where hand-made and grid inputs put their nodes.
constexpr double kRayAngle = 0.7391;

struct HalfInfo {
  int site = kNone;
  int start = kNone;  // node, kNone at infinity
  int end = kNone;
};

int half_id(int arc, bool forward) { return 2 * arc + (forward ? 0 : 1); }
HalfArc half_of(int id) { return {id / 2, id % 2 == 0}; }

HalfInfo info(const Diagram& d, int id) {
  const Arc& a = d.arcs[id / 2];
  const bool fwd = id % 2 == 0;
  return {fwd ? a.left_site : a.right_site, fwd ? a.from : a.to, fwd ? a.to : a.from};
}

// A point at infinity: the direction angle, and the offset that orders parallel arcs.
struct AtInfinity {
  double angle = 0.0;
  double offset = 0.0;
};

AtInfinity infinity_key(const Diagram& d, int id, bool leaving) {
  const Arc& a = d.arcs[id / 2];
  const Line& l = std::get<Line>(a.curve);
  const double len = std::hypot(l.dx, l.dy);
  Point u{l.dx / len, l.dy / len};
  const bool fwd = id % 2 == 0;
  // Leaving forward goes to +u; arriving forward comes from -u; backward the opposite.
  if (leaving != fwd) u = {-u.x, -u.y};
  double angle = std::atan2(u.y, u.x);
  if (angle < 0) angle += kTwoPi;
  // Counter-clockwise at infinity = along rot90(u).
  return {angle, -l.x * u.y + l.y * u.x};
}

bool key_less(const AtInfinity& a, const AtInfinity& b) {
  if (std::fabs(a.angle - b.angle) > tolerance::kParallelAngle) return a.angle < b.angle;
  return a.offset < b.offset;
}

// Counter-clockwise angular distance from a to b in [0, 2π).
double ccw_distance(double a, double b) {
  double x = b - a;
  while (x < 0) x += kTwoPi;
  while (x >= kTwoPi) x -= kTwoPi;
  return x;
}

}  // namespace

namespace {

// Ray casting along kRayAngle; `path_of(arc)` gives each arc's path (cached by trace_faces).
template <class PathOf>
bool contains_with(const Diagram& d, std::span<const HalfArc> cycle, Point p, PathOf&& path_of) {
  const Point dir{std::cos(kRayAngle), std::sin(kRayAngle)};
  int crossings = 0;
  for (std::size_t k = 0; k < cycle.size(); ++k) {
    const HalfArc h = cycle[k];
    const ArcPathView& path = path_of(h.arc);
    if (path.circle) {
      // p + t dir on the circle, t > 0, at a parameter inside the arc.
      const double fx = p.x - path.cx, fy = p.y - path.cy;
      const double b = fx * dir.x + fy * dir.y, c = fx * fx + fy * fy - path.r * path.r;
      const double disc = b * b - c;
      if (disc > 0) {
        const double sq = std::sqrt(disc);
        for (double t : {-b - sq, -b + sq}) {
          if (t <= 0) continue;
          const double x = fx + t * dir.x, y = fy + t * dir.y;
          double s = path.sense * (std::atan2(y, x) - path.start_angle);
          s = std::fmod(s, kTwoPi);
          if (s < 0) s += kTwoPi;
          if (s > path.s0 && s < path.s1) ++crossings;
        }
      }
    } else {
      const double den = dir.x * path.uy - dir.y * path.ux;
      if (den != 0) {
        const double wx = path.ox - p.x, wy = path.oy - p.y;
        const double t = (wx * path.uy - wy * path.ux) / den;
        const double s = (wx * dir.y - wy * dir.x) / den;
        if (t > 0 && s > path.s0 && s < path.s1) ++crossings;
      }
    }
    // A passage through infinity to the next half-arc: counter-clockwise from where this one
    // leaves to where the next arrives; the ray meets it if its direction lies in between.
    const int id = half_id(h.arc, h.forward);
    const HalfArc nx = cycle[(k + 1) % cycle.size()];
    if (info(d, id).end == kNone && !path.circle) {
      const double out = infinity_key(d, id, true).angle;
      const double in = infinity_key(d, half_id(nx.arc, nx.forward), false).angle;
      const double span = ccw_distance(out, in);
      const double ray = ccw_distance(out, kRayAngle);
      if (span > tolerance::kParallelAngle && ray < span) ++crossings;
    }
  }
  return crossings % 2 == 1;
}

}  // namespace

bool cycle_contains(const Diagram& d, std::span<const HalfArc> cycle, Point p) {
  ArcPathView scratch;
  return contains_with(d, cycle, p, [&](int arc) -> const ArcPathView& {
    scratch = arc_path(d.arcs[arc], d.nodes);
    return scratch;
  });
}

namespace {

// Boxes kept per arc in single precision, rounded outward (half the memory of doubles; a box only
// preselects). Coordinates beyond float range become infinite: such a box is treated as unbounded.
using FloatBox = std::array<float, 4>;

FloatBox to_float_outward(const Box& b) {
  auto down = [](double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -INFINITY) : f;
  };
  auto up = [](double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, INFINITY) : f;
  };
  return {down(b.xmin), down(b.ymin), up(b.xmax), up(b.ymax)};
}

Box to_double(const FloatBox& f) { return {f[0], f[1], f[2], f[3]}; }  // FloatBox: xmin, ymin, xmax, ymax


// Per half-arc geometry at the node where it starts: the pseudo-angle of its direction of travel and its
// curvature in that direction (next_of compares them at every node); per arc, twice the signed
// area between the forward half-arc and its chord (positive when it bulges to the right).
struct TracingGeometry {
  struct Departure {
    double angle = 0.0;
    double curvature = 0.0;
  };
  LargeVector<Departure> depart;  // per half-arc, angle and curvature side by side (read together)
  LargeVector<double> segment_area2;
  LargeVector<FloatBox> box;  // per arc, when asked for (placing holes by geometry)
};

// The arcs' end nodes are read here once for everything that needs them (they are scattered in
// memory: each read is a cache miss at 10^6 faces).
TracingGeometry tracing_geometry(const Diagram& d, bool with_boxes) {
  const std::size_t arcs = d.arcs.size();
  TracingGeometry g;
  g.depart.assign(2 * arcs, {});
  g.segment_area2.assign(arcs, 0.0);
  if (with_boxes) g.box.resize(arcs);
  // Independent per arc: both cores share it (engine/parallel.h).
  parallel_chunks(arcs, worker_count(arcs), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t a = b; a < e; ++a) {
      const Arc& arc = d.arcs[a];
      const Node none{};
      const Node& from = arc.from == kNone ? none : d.nodes[arc.from];
      const Node& to = arc.to == kNone ? none : d.nodes[arc.to];
      if (with_boxes) g.box[a] = to_float_outward(arc_bounds(arc, from, to));
      if (const Circle* c = std::get_if<Circle>(&arc.curve)) {
        const double sense = arc.ccw ? 1.0 : -1.0;
        double sweep = kTwoPi;
        if (arc.from != kNone) {
          const double ax = from.x - c->cx, ay = from.y - c->cy;
          const double ex = to.x - c->cx, ey = to.y - c->cy;
          // Forward travel at the start: the radius turned by +90° (counter-clockwise arcs);
          // backward travel at the end: the reverse of forward travel there.
          g.depart[2 * a] = {pseudo_angle(sense * -ay, sense * ax), sense / c->r};
          g.depart[2 * a + 1] = {pseudo_angle(-sense * -ey, -sense * ex), -sense / c->r};
          if (arc.from != arc.to) {
            sweep = sense * std::atan2(ax * ey - ay * ex, ax * ex + ay * ey);
            if (sweep <= 0) sweep += kTwoPi;
          }
        }
        g.segment_area2[a] = sense * c->r * c->r * (sweep - std::sin(sweep));
      } else {
        const Line& l = std::get<Line>(arc.curve);
        if (arc.from != kNone) g.depart[2 * a].angle = pseudo_angle(l.dx, l.dy);
        if (arc.to != kNone) g.depart[2 * a + 1].angle = pseudo_angle(-l.dx, -l.dy);
      }
    }
  });
  return g;
}

// The box holding the central 98 % of the nodes in each coordinate: far arcs of nearly tangent
// bisectors would otherwise stretch a grid's cells over the whole diagram.
// Only grid bounds depend on it (boxes outside land in the border cells), so a regular sample of at
// most 2^16 nodes stands in for all of them.
Box central_box(const std::vector<Node>& nodes) {
  LargeVector<double> xs, ys;
  const std::size_t stride = std::max<std::size_t>(1, nodes.size() >> 16);
  for (std::size_t k = 0; k < nodes.size(); k += stride) {
    const Node& n = nodes[k];
    if (std::isfinite(n.x) && std::isfinite(n.y)) xs.push_back(n.x), ys.push_back(n.y);
  }
  if (xs.empty()) return Box{};
  return central_extent(std::move(xs), std::move(ys));
}

}  // namespace

void trace_faces(Diagram& d, FaceLabels labels, FaceIndex* index) {
  d.faces.clear();
  const bool by_sites = labels == FaceLabels::kSites;
  // The region a half-arc bounds: its site, or (by geometry) one common label, so that every
  // continuation at a node is chosen by angle.
  auto label = [&](int h) { return by_sites ? info(d, h).site : 0; };
  const int halves = 2 * static_cast<int>(d.arcs.size());
  const TracingGeometry geometry = tracing_geometry(d, !by_sites);
  // Outgoing half-arcs per node in compressed rows (out_begin[v] .. out_begin[v+1]), and
  // half-arcs arriving from infinity per site.
  LargeVector<int> out_begin(d.nodes.size() + 1, 0), out_list;
  std::map<int, std::vector<int>> from_infinity;
  for (int h = 0; h < halves; ++h) {
    const HalfInfo hi = info(d, h);
    if (label(h) == kNone) continue;
    if (hi.start == kNone) {
      if (hi.end != kNone || std::holds_alternative<Line>(d.arcs[h / 2].curve))
        from_infinity[label(h)].push_back(h);
    } else {
      ++out_begin[hi.start + 1];
    }
  }
  for (std::size_t v = 0; v < d.nodes.size(); ++v) out_begin[v + 1] += out_begin[v];
  out_list.resize(out_begin.back());
  {
    LargeVector<int> fill(out_begin.begin(), out_begin.end() - 1);
    for (int h = 0; h < halves; ++h) {
      const HalfInfo hi = info(d, h);
      if (label(h) != kNone && hi.start != kNone) out_list[fill[hi.start]++] = h;
    }
  }
  auto outgoing = [&](int v) {
    return std::span<const int>(out_list.data() + out_begin[v], out_begin[v + 1] - out_begin[v]);
  };
  for (auto& [site, list] : from_infinity)
    std::sort(list.begin(), list.end(), [&](int a, int b) {
      return key_less(infinity_key(d, a, false), infinity_key(d, b, false));
    });

  // The continuation of half-arc h at the node where it ends, among the outgoing half-arcs
  // `out` there that `eligible` admits. The region touches this node more than once (or faces are
  // traced by geometry): take the first outgoing arc clockwise from the reversed incoming
  // direction (the face is on the left); of arcs leaving in the same direction, the one bending
  // more to the left lies at larger angles next to the node, so the clockwise sweep from the back
  // direction meets it first. The reversed incoming direction is the departure of the twin h ^ 1.
  auto turn_at = [&](std::span<const int> out, int h, auto&& eligible) {
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
  };
  auto next_of = [&](int h) -> int {
    const HalfInfo hi = info(d, h);
    const Arc& arc = d.arcs[h / 2];
    if (hi.end == kNone) {
      if (hi.start == kNone && std::holds_alternative<Circle>(arc.curve)) return h;  // full circle
      // Around infinity, counter-clockwise, to the next arc of this site coming back.
      const auto found = from_infinity.find(label(h));  // read-only: next_of runs on several threads
      if (found == from_infinity.end() || found->second.empty()) return -1;
      const auto& list = found->second;
      const AtInfinity leave = infinity_key(d, h, true);
      for (int c : list)
        if (key_less(leave, infinity_key(d, c, false))) return c;
      return list.front();
    }
    int best = -1;
    int count = 0;
    for (int c : outgoing(hi.end))
      if (label(c) == label(h)) {
        ++count;
        best = c;
      }
    if (count <= 1) return best;
    return turn_at(outgoing(hi.end), h, [&](int c) { return label(c) == label(h); });
  };

  // The continuation of every half-arc, computed once (in parallel; next_of only reads).
  LargeVector<int> next_half(halves, -1);
  if (by_sites) {
    parallel_chunks(static_cast<std::size_t>(halves), worker_count(halves), [&](std::size_t b, std::size_t e, int) {
      for (int h = static_cast<int>(b); h < static_cast<int>(e); ++h)
        if (label(h) != kNone) next_half[h] = next_of(h);
    });
  } else {
    // By geometry every arc at a node is eligible, so the continuations are settled node by node:
    // each half-arc arriving at v is the twin of one leaving it, and all the data is v's own.
    const std::size_t nodes = d.nodes.size();
    if (index) index->degenerate_node.resize(nodes);
    parallel_chunks(nodes, worker_count(nodes), [&](std::size_t b, std::size_t e, int) {
      for (std::size_t v = b; v < e; ++v) {
        const auto out = outgoing(static_cast<int>(v));
        for (int c : out) next_half[c ^ 1] = turn_at(out, c ^ 1, [](int) { return true; });
        if (!index) continue;
        bool degenerate = out.size() != 3;
        for (std::size_t i = 0; i < out.size() && !degenerate; ++i)
          for (std::size_t j = i + 1; j < out.size(); ++j) {
            // Tangent curves: directions equal or opposite (pseudo-angles differ by 0, 2 or 4).
            const double diff = std::abs(geometry.depart[out[i]].angle - geometry.depart[out[j]].angle);
            const double off = std::min({diff, std::abs(diff - 0.5 * kPseudoTurn), std::abs(diff - kPseudoTurn)});
            if (off < tolerance::kParallelAngle) degenerate = true;
          }
        index->degenerate_node[v] = degenerate;
      }
    });
    parallel_chunks(static_cast<std::size_t>(halves), worker_count(halves), [&](std::size_t b, std::size_t e, int) {
      for (int h = static_cast<int>(b); h < static_cast<int>(e); ++h)
        if (info(d, h).end == kNone) next_half[h] = next_of(h);
    });
  }

  // Closed cycles, stored one after the other in `cycle_halves` (no vector per cycle: a graph of
  // 10^6 faces would spend more time allocating than tracing).
  struct Cycle {
    int site = kNone;
    int begin = 0, end = 0;  // range in cycle_halves
    bool through_infinity = false;
    double area2 = 0.0;  // twice the signed area (closed cycles)
  };
  LargeVector<Cycle> cycles;
  cycles.reserve(static_cast<std::size_t>(halves) / 2);  // a hint: most cycles have two or more half-arcs
  LargeVector<int> cycle_halves;
  cycle_halves.reserve(halves);
  LargeVector<int> cycle_of_half(halves, -1);
  LargeVector<char> seen(halves, 0);
  // The walk only follows next_half (memory latency bound); orientation and the rest are computed
  // per cycle afterwards, on both cores.
  auto walk_sequentially = [&]() {
    for (int h0 = 0; h0 < halves; ++h0) {
      if (seen[h0] || label(h0) == kNone) continue;
      Cycle cyc;
      cyc.site = label(h0);
      cyc.begin = static_cast<int>(cycle_halves.size());
      int h = h0;
      bool closed = false;
      for (int guard = 0; guard <= halves; ++guard) {
        seen[h] = 1;
        cycle_halves.push_back(h);
        const int nx = next_half[h];
        if (nx < 0) break;
        if (nx == h0) {
          closed = true;
          break;
        }
        if (seen[nx]) break;
        h = nx;
      }
      if (!closed) {
        cycle_halves.resize(cyc.begin);
        continue;
      }
      cyc.end = static_cast<int>(cycle_halves.size());
      cycles.push_back(cyc);
    }
  };
  // By geometry next_half is a permutation of the half-arcs (every half-arc has one successor and
  // one predecessor), and its cycles can be walked on both cores: each cycle by the worker whose
  // range holds its smallest half-arc, which is where the sequential walk starts it too, so the
  // cycles come out in the same order. A walk from any other half-arc stops at the first smaller
  // one. Anything but a permutation (a dangling end, a walk that does not come back) is left to the
  // sequential walk.
  auto walk_in_parallel = [&]() {
    const int workers = worker_count(static_cast<std::size_t>(halves));
    std::vector<LargeVector<Cycle>> found(workers);
    std::vector<LargeVector<int>> walked(workers);
    std::atomic<bool> malformed{false};
    parallel_chunks(static_cast<std::size_t>(halves), workers, [&](std::size_t b, std::size_t e, int w) {
      LargeVector<int>& out = walked[w];
      out.reserve(e - b + 64);  // the cycles owned by a range have about as many half-arcs as it
      found[w].reserve((e - b) / 2);
      for (int h0 = static_cast<int>(b); h0 < static_cast<int>(e) && !malformed.load(std::memory_order_relaxed); ++h0) {
        if (std::atomic_ref<char>(seen[h0]).load(std::memory_order_relaxed)) continue;
        const std::size_t begin = out.size();
        int h = h0;
        bool owner = false;
        for (int guard = 0;; ++guard) {
          out.push_back(h);
          const int nx = next_half[h];
          if (nx < 0 || guard > halves) {
            malformed = true;
            break;
          }
          if (nx == h0) {
            owner = true;
            break;
          }
          if (nx < h0) break;  // the cycle's walk starts at a smaller half-arc
          h = nx;
        }
        if (!owner) {
          out.resize(begin);
          continue;
        }
        for (std::size_t k = begin; k < out.size(); ++k) std::atomic_ref<char>(seen[out[k]]).store(1, std::memory_order_relaxed);
        found[w].push_back(Cycle{0, static_cast<int>(begin), static_cast<int>(out.size()), false, 0.0});
      }
    });
    if (malformed) {
      std::fill(seen.begin(), seen.end(), 0);
      return false;
    }
    for (int w = 0; w < workers; ++w) {
      const int offset = static_cast<int>(cycle_halves.size());
      cycle_halves.insert(cycle_halves.end(), walked[w].begin(), walked[w].end());
      for (Cycle c : found[w]) {
        c.begin += offset, c.end += offset;
        cycles.push_back(c);
      }
    }
    return true;
  };
  if (by_sites || !walk_in_parallel()) walk_sequentially();
  parallel_chunks(cycles.size(), worker_count(cycles.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t c = b; c < e; ++c) {
      Cycle& cyc = cycles[c];
      // Orientation by signed area: chords (shoelace about the first node, against cancellation
      // far from the origin) plus the circular segments between chords and arcs.
      const int origin_node = info(d, cycle_halves[cyc.begin]).start;
      const Point o = origin_node == kNone ? Point{0, 0} : Point{d.nodes[origin_node].x, d.nodes[origin_node].y};
      for (int k = cyc.begin; k < cyc.end; ++k) {
        const int h = cycle_halves[k];
        cycle_of_half[h] = static_cast<int>(c);
        const HalfInfo hi = info(d, h);
        cyc.area2 += (h % 2 == 0 ? 1.0 : -1.0) * geometry.segment_area2[h / 2];
        if (hi.start != kNone && hi.end != kNone) {
          const Node& a = d.nodes[hi.start];
          const Node& b = d.nodes[hi.end];
          cyc.area2 += (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y);
        }
        if (hi.end == kNone && std::holds_alternative<Line>(d.arcs[h / 2].curve)) cyc.through_infinity = true;
      }
    }
  });
  auto halves_of = [&](const Cycle& c) {
    return std::span<const int>(cycle_halves.data() + c.begin, static_cast<std::size_t>(c.end - c.begin));
  };
  // All cycles as half-arcs, in one array that the faces share (FaceBoundaries): no allocation per
  // face. Advised as huge pages before the first touch, filled on both cores.
  const auto pool = std::make_shared<std::vector<HalfArc>>();
  pool->reserve(cycle_halves.size());
  advise_huge_pages(pool->data(), pool->capacity() * sizeof(HalfArc));
  pool->resize(cycle_halves.size());
  parallel_chunks(cycle_halves.size(), worker_count(cycle_halves.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t k = b; k < e; ++k) (*pool)[k] = half_of(cycle_halves[k]);
  });
  auto add_cycle = [&](Face& face, const Cycle& c) {
    face.boundaries.push_back_shared(pool, static_cast<std::size_t>(c.begin), static_cast<std::size_t>(c.end));
  };

  // Outer cycles make faces; clockwise cycles are holes of the face of their site containing them.
  std::unordered_map<int, LargeVector<int>> faces_of_site;
  std::vector<int> holes;                  // cycle indices
  LargeVector<int> face_of_cycle(cycles.size(), -1), hole_of_cycle(cycles.size(), -1);
  LargeVector<double> outer_area;          // per face: |area| of its outer cycle (∞ when unbounded)
  // Faces: one per outer cycle, plus at most one per hole (a site's unbounded face made for its
  // holes), so no reallocation of a million faces when the first of those appears.
  d.faces.reserve(cycles.size() + 1);
  advise_huge_pages(d.faces.data(), d.faces.capacity() * sizeof(Face));
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    const Cycle& cyc = cycles[c];
    if (cyc.through_infinity || cyc.area2 > 0) {
      outer_area.push_back(cyc.through_infinity ? INFINITY : cyc.area2);
      face_of_cycle[c] = static_cast<int>(d.faces.size());
      faces_of_site[cyc.site].push_back(static_cast<int>(d.faces.size()));
      d.faces.push_back(Face{by_sites ? cyc.site : kNone, !cyc.through_infinity, false, {}});
    } else {
      hole_of_cycle[c] = static_cast<int>(holes.size());
      holes.push_back(static_cast<int>(c));
    }
  }
  // Each face's outer cycle (sequential: the faces share one reference count).
  for (std::size_t c = 0; c < cycles.size(); ++c)
    if (face_of_cycle[c] >= 0) add_cycle(d.faces[face_of_cycle[c]], cycles[c]);
  const LargeVector<char> has_outer(d.faces.size(), 1);
  // The face whose outer cycle runs along each half-arc (-1 on holes): the face across a hole's own
  // arcs is the one on the hole's other side, never the face containing it.
  auto outer_face_of_half = [&](int h) {
    const int c = cycle_of_half[h];
    return c < 0 || hole_of_cycle[c] >= 0 ? -1 : face_of_cycle[c];
  };
  std::map<int, int> implicit_face;  // site -> its unbounded face without outer cycle
  // The unbounded component of a site without lines has no outer cycle, only holes: one face per
  // site (per graph when tracing by geometry), made on first use.
  auto implicit_face_of = [&](int site) {
    auto it = implicit_face.find(site);
    if (it == implicit_face.end()) {
      Face f;
      f.site = by_sites ? site : kNone;
      f.bounded = false;
      faces_of_site[site].push_back(static_cast<int>(d.faces.size()));
      d.faces.push_back(std::move(f));
      it = implicit_face.emplace(site, static_cast<int>(d.faces.size()) - 1).first;
    }
    return it->second;
  };
  auto path_of_arc = [&](int arc) { return arc_path(d.arcs[arc], d.nodes); };
  // Paths for the containment tests of holes the ray cannot place (every hole when tracing by
  // sites): computed on first use and kept, since one large face's outer cycle is tested against
  // many holes.
  LargeVector<ArcPathView> path_cache;
  LargeVector<char> path_cached;
  auto cached_path = [&](int arc) -> const ArcPathView& {
    if (path_cache.empty()) {
      path_cache.resize(d.arcs.size());
      path_cached.assign(d.arcs.size(), 0);
    }
    if (!path_cached[arc]) path_cache[arc] = path_of_arc(arc), path_cached[arc] = 1;
    return path_cache[arc];
  };
  // Candidate outer cycles for a point, through a grid over their bounding boxes (built on first
  // use: most graphs have no hole that needs a containment test). Without it, tracing by geometry
  // (one label for all faces) would test every hole against every face.
  std::optional<BoxGrid> face_grid;
  auto candidate_faces = [&](Point p) {
    if (!face_grid) {
      LargeVector<Box> boxes(outer_area.size(), Box{});
      for (std::size_t f = 0; f < outer_area.size(); ++f)
        for (const HalfArc& h : d.faces[f].boundaries.front()) {
          const Box b = arc_bounds(d.arcs[h.arc], d.nodes);
          boxes[f].add_box(b);
        }
      // Over the central nodes: a few faces reaching far out would otherwise stretch the cells
      // until every face shares one.
      face_grid = make_grid(boxes.size(), [&](std::size_t f) { return boxes[f]; }, central_box(d.nodes), outer_area.size(),
                            /*max_cells=*/64);
    }
    std::vector<int> out(face_grid->always.begin(), face_grid->always.end());
    if (face_grid->nx > 0) {  // clamped like the boxes: a point beyond the grid meets the border cells
      const auto c = face_grid->cell(face_grid->column(p.x), face_grid->row(p.y));
      out.insert(out.end(), c.begin(), c.end());
    }
    return out;
  };
  // Tracing by geometry, every hole would be tested against every outer cycle around it. Instead
  // each hole shoots a ray to +x from its rightmost point (there its containing face lies just to
  // the right) and takes the first arc hit: the half-arc facing the ray's origin bounds the same
  // face, as its outer cycle or as another hole. Holes whose ray meets nothing, or meets an arc at a
  // node (ambiguous), fall back to containment tests.
  std::vector<int> ray_face(holes.size(), -2);  // face, -1 unbounded, -2 undecided
  if (!by_sites && !holes.empty()) {
    // A few holes in a small graph (the usual case: the outer boundary of a weighted diagram)
    // are cheaper to test against every arc than to grid all arcs for.
    const bool scan_all = holes.size() * d.arcs.size() <= (std::size_t{1} << 22);
    auto box_of = [&](std::size_t a) { return to_double(geometry.box[a]); };
    auto unbounded_line = [&](std::size_t a) {
      return std::holds_alternative<Line>(d.arcs[a].curve) && (d.arcs[a].from == kNone || d.arcs[a].to == kNone);
    };
    std::vector<int> unbounded_arcs;
    for (std::size_t a = 0; a < d.arcs.size(); ++a)
      if (unbounded_line(a)) unbounded_arcs.push_back(static_cast<int>(a));
    const Box nodes_box = central_box(d.nodes);
    BoxGrid arc_grid;
    // About four arcs per cell: a ray crosses few cells before its first hit, and a coarser grid
    // is cheaper to fill.
    // Far arcs of huge circles land in the border cells, which only rays that go that far reach;
    // an arc whose box spans more than four rows' worth of cells (around the whole graph) is
    // tested by every ray instead of filling the grid.
    if (!scan_all) {
      const std::size_t cells = d.arcs.size() / 4;
      arc_grid = make_grid(d.arcs.size(), box_of, nodes_box, cells, 4 * static_cast<long long>(std::sqrt(static_cast<double>(cells))) + 64);
    }
    // Crossings of the horizontal line y with arc a (box b): (x, tangent y-component) pairs.
    std::vector<std::pair<double, double>> xs;
    auto crossings = [&](int a, const Box& b, double y) {
      xs.clear();
      if (!(b.ymin <= y && y <= b.ymax)) return;
      const ArcPathView p = path_of_arc(a);
      if (p.circle) {
        const double dy = y - p.cy;
        const double h2 = p.r * p.r - dy * dy;
        if (h2 <= 0) return;
        const double h = std::sqrt(h2);
        for (double x : {p.cx - h, p.cx + h}) {
          double s = std::fmod(p.sense * (std::atan2(dy, x - p.cx) - p.start_angle), kTwoPi);
          if (s < 0) s += kTwoPi;
          // A full circle has no end where the ray could pass through a node: its start angle
          // is an ordinary point (concentric circles are hit exactly there).
          const bool full = d.arcs[a].from == kNone;
          if ((s > p.s0 && s < p.s1) || full) xs.emplace_back(x, p.tangent(s).y);
        }
      } else if (p.uy != 0) {
        const double s = (y - p.oy) / p.uy;
        if (s > p.s0 && s < p.s1) xs.emplace_back(p.ox + s * p.ux, p.uy);
      }
    };
    LargeVector<int> stamp(d.arcs.size(), -1);
    const double eps_x = nodes_box.finite()
                             ? tolerance::kRayTie * std::max(nodes_box.xmax - nodes_box.xmin, nodes_box.ymax - nodes_box.ymin)
                             : 0.0;
    for (std::size_t k = 0; k < holes.size(); ++k) {
      // Rightmost point of the hole.
      Point right{-INFINITY, 0};
      for (int hh : halves_of(cycles[holes[k]])) {
        const ArcPathView p = path_of_arc(hh / 2);
        auto consider = [&](Point q) {
          if (q.x > right.x) right = q;
        };
        if (std::isfinite(p.s0)) consider(p.at(p.s0));
        if (std::isfinite(p.s1)) consider(p.at(p.s1));
        if (p.circle) {
          double t = std::fmod(p.sense * (0.0 - p.start_angle), kTwoPi);
          if (t < 0) t += kTwoPi;
          if (t >= p.s0 && t <= p.s1) consider(p.at(t));
        }
      }
      if (!std::isfinite(right.x)) continue;
      double best_x = INFINITY, best_ty = 0;
      int best_arc = -1;
      bool ambiguous = false;
      auto test_arc = [&](int a) {
        const Box b = box_of(static_cast<std::size_t>(a));
        if (b.xmax <= right.x) return;  // wholly left of the ray's origin
        crossings(a, b, right.y);
        for (auto [x, ty] : xs) {
          if (x <= right.x + eps_x) continue;
          if (std::abs(x - best_x) <= eps_x) ambiguous = true;
          if (x < best_x) best_x = x, best_ty = ty, best_arc = a, ambiguous = false;
        }
      };
      if (!scan_all && arc_grid.nx == 0) continue;  // no finite extent to grid: containment tests
      if (scan_all)
        for (int a : unbounded_arcs) test_arc(a);
      else
        for (int a : arc_grid.always) test_arc(a);
      if (scan_all) {
        for (std::size_t a = 0; a < d.arcs.size(); ++a)
          if (!unbounded_line(a)) test_arc(static_cast<int>(a));
      } else if (arc_grid.nx > 0) {
        const int j = arc_grid.row(right.y);
        for (int i = arc_grid.column(right.x); i < arc_grid.nx; ++i) {
          if (i > 0 && best_x < arc_grid.x0 + i * arc_grid.cw) break;  // the nearest hit is left of this cell
          for (int a : arc_grid.cell(i, j)) {
            if (stamp[a] == static_cast<int>(k)) continue;  // an arc spans several cells
            stamp[a] = static_cast<int>(k);
            test_arc(a);
          }
        }
      }
      if (best_arc < 0) {
        ray_face[k] = unbounded_arcs.empty() ? -1 : -2;
        continue;
      }
      // Through a node, or tangent to the hit arc: fall back to containment tests.
      if (ambiguous || std::abs(best_ty) < tolerance::kRayTangent) continue;
      // The half-arc facing -x (the ray's origin) on its left: tangent pointing up.
      const int hit = half_id(best_arc, best_ty > 0);
      const int hit_cycle = cycle_of_half[hit];
      if (hit_cycle < 0) continue;
      if (face_of_cycle[hit_cycle] >= 0) ray_face[k] = face_of_cycle[hit_cycle];
      else if (hole_of_cycle[hit_cycle] != static_cast<int>(k)) ray_face[k] = -3 - hole_of_cycle[hit_cycle];
    }
    // Resolve chains of holes (-3 - other) to faces.
    for (std::size_t k = 0; k < holes.size(); ++k) {
      int v = ray_face[k], steps = 0;
      while (v <= -3 && steps++ <= static_cast<int>(holes.size())) v = ray_face[-3 - v];
      ray_face[k] = v <= -3 ? -2 : v;
    }
  }
  for (std::size_t hk = 0; hk < holes.size(); ++hk) {
    const Cycle& hole = cycles[holes[hk]];
    if (ray_face[hk] != -2) {
      int target = ray_face[hk];
      if (target < 0) target = implicit_face_of(hole.site);
      add_cycle(d.faces[target], hole);
      face_of_cycle[holes[hk]] = target;
      continue;
    }
    const HalfArc first = half_of(cycle_halves[hole.begin]);
    const ArcPathView path = arc_path(d.arcs[first.arc], d.nodes);
    const double mid = std::isfinite(path.s0) && std::isfinite(path.s1) ? 0.5 * (path.s0 + path.s1)
                       : std::isfinite(path.s0)                          ? path.s0 + 1.0
                       : std::isfinite(path.s1)                          ? path.s1 - 1.0
                                                                         : 0.0;
    const Point p = path.at(mid);
    int target = -1;
    std::vector<int> across;
    for (int h : halves_of(hole)) across.push_back(outer_face_of_half(h ^ 1));
    for (int f : candidate_faces(p)) {
      if (d.faces[f].site != (by_sites ? hole.site : kNone)) continue;
      if (f >= static_cast<int>(outer_area.size())) continue;  // hole-only faces have no outer
      if (std::find(across.begin(), across.end(), f) != across.end()) continue;
      // Innermost containing outer cycle (smallest area) wins.
      if (contains_with(d, d.faces[f].boundaries.front(), p, cached_path) && (target < 0 || outer_area[f] < outer_area[target]))
        target = f;
    }
    if (target < 0) {
      target = implicit_face_of(hole.site);
    }
    add_cycle(d.faces[target], hole);
    face_of_cycle[holes[hk]] = target;
  }
  if (index) {
    index->face_of_half.assign(halves, kNone);
    index->next_half = std::move(next_half);
    for (int h = 0; h < halves; ++h) {
      if (cycle_of_half[h] < 0) index->next_half[h] = kNone;
      else index->face_of_half[h] = face_of_cycle[cycle_of_half[h]];
    }
  }
  if (!by_sites) {
    if (d.faces.empty()) d.faces.push_back(Face{kNone, false, false, {}});  // no arcs: the plane
    return;
  }
  // A diagram of one site (or none with arcs): the whole plane.
  for (std::size_t s = 0; s < d.sites.size(); ++s)
    if (faces_of_site.find(static_cast<int>(s)) == faces_of_site.end() && d.arcs.empty() &&
        d.clip.empty()) {
      Face f;
      f.site = static_cast<int>(s);
      f.bounded = false;
      faces_of_site[f.site].push_back(static_cast<int>(d.faces.size()));
      d.faces.push_back(std::move(f));
    }

  // Orphans: every face of a site but the one containing the site itself. Faces created for holes
  // only (the unbounded component of a site without lines) have no outer cycle.
  for (auto& [site, list] : faces_of_site) {
    const Point s{d.sites[site].x, d.sites[site].y};
    // Unclipped, a site lies in its own region: a single face is its own.
    if (list.size() == 1 && d.clip.empty()) {
      d.faces[list.front()].orphan = false;
      continue;
    }
    for (int f : list) {
      Face& face = d.faces[f];
      const bool outer = f < static_cast<int>(has_outer.size()) && has_outer[f];
      bool inside = !outer || cycle_contains(d, face.boundaries.front(), s);
      for (std::size_t b = outer ? 1 : 0; inside && b < face.boundaries.size(); ++b)
        if (cycle_contains(d, face.boundaries[b], s)) inside = false;
      face.orphan = !inside;
    }
  }
}

}  // namespace covmap::voronoi
