#include "voronoi/faces.h"

#include "voronoi/engine/parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <span>
#include <unordered_map>

#include "voronoi/arc_path.h"
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

// Direction of travel of a half-arc at its start (at = 0) or end (at = 1).
Point travel_direction(const ArcPathView& p, int id, int at) {
  const bool fwd = id % 2 == 0;
  const bool at_path_start = (at == 0) == fwd;
  Point t = p.tangent(at_path_start ? p.s0 : p.s1);
  if (!p.circle && !std::isfinite(at_path_start ? p.s0 : p.s1)) t = p.tangent(0);
  if (!fwd) t = {-t.x, -t.y};
  return t;
}

// Twice the signed area between a half-arc and its chord (positive when the half-arc bulges to the
// right of its direction, i.e. when it runs counter-clockwise around its circle).
double segment_area2(const ArcPathView& p, int id) {
  if (!p.circle) return 0.0;
  const double sweep = p.s1 - p.s0;
  const double travel_sense = id % 2 == 0 ? p.sense : -p.sense;
  return travel_sense * p.r * p.r * (sweep - std::sin(sweep));
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
bool contains_with(const Diagram& d, const std::vector<HalfArc>& cycle, Point p, PathOf&& path_of) {
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

bool cycle_contains(const Diagram& d, const std::vector<HalfArc>& cycle, Point p) {
  ArcPathView scratch;
  return contains_with(d, cycle, p, [&](int arc) -> const ArcPathView& {
    scratch = arc_path(d.arcs[arc], d.nodes);
    return scratch;
  });
}

void trace_faces(Diagram& d, FaceLabels labels) {
  d.faces.clear();
  const bool by_sites = labels == FaceLabels::kSites;
  // The region a half-arc bounds: its site, or (by geometry) one common label, so that every
  // continuation at a node is chosen by angle.
  auto label = [&](int h) { return by_sites ? info(d, h).site : 0; };
  const int halves = 2 * static_cast<int>(d.arcs.size());
  std::vector<ArcPathView> paths;
  // Per-arc and per-half-arc geometry is independent work: both cores share it (engine/parallel.h).
  paths.resize(d.arcs.size());
  engine::parallel_chunks(d.arcs.size(), engine::worker_count(d.arcs.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t a = b; a < e; ++a) paths[a] = arc_path(d.arcs[a], d.nodes);
  });
  auto path_of = [&](int h) -> const ArcPathView& { return paths[h / 2]; };
  // Outgoing half-arcs per node, and half-arcs arriving from infinity per site.
  // Outgoing half-arcs per node in compressed rows (out_begin[v] .. out_begin[v+1]).
  std::vector<int> out_begin(d.nodes.size() + 1, 0), out_list;
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
    std::vector<int> fill(out_begin.begin(), out_begin.end() - 1);
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

  // Per half-arc: the angle of its direction of travel where it starts, and its curvature in that
  // direction (computed once; next_of compares them at every node).
  std::vector<double> depart_angle(halves, 0.0), depart_curvature(halves, 0.0);
  engine::parallel_chunks(static_cast<std::size_t>(halves), engine::worker_count(halves), [&](std::size_t b, std::size_t e, int) {
    for (int h = static_cast<int>(b); h < static_cast<int>(e); ++h) {
      if (info(d, h).start == kNone) continue;
      const Point t = travel_direction(path_of(h), h, 0);
      depart_angle[h] = std::atan2(t.y, t.x);
      depart_curvature[h] = path_of(h).curvature() * (h % 2 == 0 ? 1.0 : -1.0);
    }
  });
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
    // The region touches this node more than once (or faces are traced by geometry): take the
    // first outgoing arc clockwise from the reversed incoming direction (the face is on the left);
    // of arcs leaving in the same direction, the one bending more to the left lies at larger
    // angles next to the node, so the clockwise sweep from the back direction meets it first.
    // The reversed incoming direction is the departure of the twin half-arc h ^ 1.
    const double back_angle = depart_angle[h ^ 1];
    const double back_curvature = depart_curvature[h ^ 1];
    double best_angle = 1e9, best_curvature = 0.0;
    for (int c : outgoing(hi.end)) {
      if (label(c) != label(h) || c == (h ^ 1)) continue;
      // Clockwise angle from the back direction to c's departure, in (0, 2π].
      double cw = std::fmod(back_angle - depart_angle[c], kTwoPi);
      if (cw <= 0) cw += kTwoPi;
      const double k = depart_curvature[c];
      // Leaving along the way we came: right of the returning arc (bending less left) comes first
      // in the sweep, left of it last.
      if (cw < tolerance::kParallelAngle || cw > kTwoPi - tolerance::kParallelAngle)
        cw = k < back_curvature ? 0.0 : kTwoPi;
      if (best < 0 || cw < best_angle - tolerance::kParallelAngle ||
          (cw <= best_angle + tolerance::kParallelAngle && k > best_curvature))
        best_angle = cw, best_curvature = k, best = c;
    }
    if (best < 0) best = h ^ 1;  // a dangling end: come back along the same arc
    return best;
  };

  // The continuation of every half-arc, computed once (in parallel; next_of only reads).
  std::vector<int> next_half(halves, -1);
  engine::parallel_chunks(static_cast<std::size_t>(halves), engine::worker_count(halves), [&](std::size_t b, std::size_t e, int) {
    for (int h = static_cast<int>(b); h < static_cast<int>(e); ++h)
      if (label(h) != kNone) next_half[h] = next_of(h);
  });
  std::vector<char> seen(halves, 0);
  struct Cycle {
    int site;
    std::vector<HalfArc> arcs;
    bool through_infinity = false;
    double area2 = 0.0;  // twice the signed area (closed cycles)
  };
  std::vector<Cycle> cycles;
  for (int h0 = 0; h0 < halves; ++h0) {
    if (seen[h0] || label(h0) == kNone) continue;
    Cycle cyc{label(h0), {}, false, 0.0};
    int h = h0;
    bool closed = false;
    // Orientation by signed area: chords (shoelace about the first node, against cancellation
    // far from the origin) plus the circular segments between chords and arcs.
    const int origin_node = info(d, h0).start;
    const Point o = origin_node == kNone ? Point{0, 0} : Point{d.nodes[origin_node].x, d.nodes[origin_node].y};
    for (int guard = 0; guard <= halves; ++guard) {
      seen[h] = 1;
      cyc.arcs.push_back(half_of(h));
      const HalfInfo hi = info(d, h);
      cyc.area2 += segment_area2(path_of(h), h);
      if (hi.start != kNone && hi.end != kNone) {
        const Node& a = d.nodes[hi.start];
        const Node& b = d.nodes[hi.end];
        cyc.area2 += (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y);
      }
      const int nx = next_half[h];
      if (nx < 0) break;
      if (hi.end == kNone && std::holds_alternative<Line>(d.arcs[h / 2].curve))
        cyc.through_infinity = true;
      if (nx == h0) {
        closed = true;
        break;
      }
      if (seen[nx]) break;
      h = nx;
    }
    if (closed) cycles.push_back(std::move(cyc));
  }
  // Outer cycles make faces; clockwise cycles are holes of the face of their site containing them.
  std::unordered_map<int, std::vector<int>> faces_of_site;
  std::vector<const Cycle*> holes;
  std::vector<double> outer_area;  // per face: |area| of its outer cycle (∞ when unbounded)
  for (const Cycle& c : cycles) {
    if (c.through_infinity || c.area2 > 0) {
      outer_area.push_back(c.through_infinity ? INFINITY : c.area2);
      Face f;
      f.site = by_sites ? c.site : kNone;
      f.bounded = !c.through_infinity;
      f.boundaries.push_back(c.arcs);
      faces_of_site[c.site].push_back(static_cast<int>(d.faces.size()));
      d.faces.push_back(std::move(f));
    } else {
      holes.push_back(&c);
    }
  }
  const std::vector<char> has_outer(d.faces.size(), 1);
  // The face whose outer cycle runs along each half-arc: the face across a hole's own arcs is the
  // one on the hole's other side, never the face containing it (the test point lies on that arc).
  std::vector<int> outer_face_of_half(halves, -1);
  for (std::size_t f = 0; f < d.faces.size(); ++f)
    for (const HalfArc& h : d.faces[f].boundaries.front())
      outer_face_of_half[half_id(h.arc, h.forward)] = static_cast<int>(f);
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
  // Candidate outer cycles for a point, through a uniform grid over their bounding boxes. Cycles
  // through infinity are always
  // candidates. Without it, tracing by geometry (one label for all faces) would test every hole
  // against every face.
  struct BoxGrid {
    double x0 = 0, y0 = 0, cell = 1;
    int nx = 1, ny = 1;
    std::vector<std::vector<int>> cells;
    std::vector<int> always;
  } grid;
  // Built on first use: most graphs have no hole that needs a containment test.
  bool grid_built = false;
  auto build_grid = [&]() {
    grid_built = true;
    std::vector<std::array<double, 4>> boxes(outer_area.size());
    double gx0 = INFINITY, gy0 = INFINITY, gx1 = -INFINITY, gy1 = -INFINITY;
    for (std::size_t f = 0; f < outer_area.size(); ++f) {
      std::array<double, 4> b = {INFINITY, INFINITY, -INFINITY, -INFINITY};
      for (const HalfArc& h : d.faces[f].boundaries.front()) {
        const ArcPathView& p = paths[h.arc];
        if (p.circle) {
          // The arc's own box: its ends and the circle's extreme points within its sweep.
          auto grow = [&](Point q) {
            b = {std::min(b[0], q.x), std::min(b[1], q.y), std::max(b[2], q.x), std::max(b[3], q.y)};
          };
          grow(p.at(p.s0));
          grow(p.at(p.s1));
          for (int k = 0; k < 4; ++k) {
            double t = p.sense * (k * 0.5 * kPi - p.start_angle);
            t = std::fmod(t, kTwoPi);
            if (t < 0) t += kTwoPi;
            if (t >= p.s0 && t <= p.s1) grow(p.at(t));
          }
        } else {
          for (double t : {p.s0, p.s1}) {
            const Point q = std::isfinite(t) ? p.at(t) : Point{INFINITY, INFINITY};
            if (!std::isfinite(q.x)) b = {-INFINITY, -INFINITY, INFINITY, INFINITY};
            else b = {std::min(b[0], q.x), std::min(b[1], q.y), std::max(b[2], q.x), std::max(b[3], q.y)};
          }
        }
      }
      boxes[f] = b;
      if (std::isfinite(b[0]) && std::isfinite(b[2])) {
        gx0 = std::min(gx0, b[0]), gy0 = std::min(gy0, b[1]);
        gx1 = std::max(gx1, b[2]), gy1 = std::max(gy1, b[3]);
      }
    }
    if (std::isfinite(gx0)) {
      const double extent = std::max(gx1 - gx0, gy1 - gy0);
      const int side = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(outer_area.size()))), 1, 2048);
      grid.x0 = gx0, grid.y0 = gy0, grid.cell = std::max(extent / side, 1e-300);
      grid.nx = std::clamp(static_cast<int>((gx1 - gx0) / grid.cell) + 1, 1, 4096);
      grid.ny = std::clamp(static_cast<int>((gy1 - gy0) / grid.cell) + 1, 1, 4096);
      grid.cells.resize(static_cast<std::size_t>(grid.nx) * grid.ny);
    }
    for (std::size_t f = 0; f < outer_area.size(); ++f) {
      const auto& b = boxes[f];
      if (!std::isfinite(b[0]) || !std::isfinite(b[2]) || grid.cells.empty()) {
        grid.always.push_back(static_cast<int>(f));
        continue;
      }
      const int i0 = std::clamp(static_cast<int>((b[0] - grid.x0) / grid.cell), 0, grid.nx - 1);
      const int i1 = std::clamp(static_cast<int>((b[2] - grid.x0) / grid.cell), 0, grid.nx - 1);
      const int j0 = std::clamp(static_cast<int>((b[1] - grid.y0) / grid.cell), 0, grid.ny - 1);
      const int j1 = std::clamp(static_cast<int>((b[3] - grid.y0) / grid.cell), 0, grid.ny - 1);
      for (int i = i0; i <= i1; ++i)
        for (int j = j0; j <= j1; ++j) grid.cells[static_cast<std::size_t>(i) * grid.ny + j].push_back(static_cast<int>(f));
    }
  };
  auto candidate_faces = [&](Point p) {
    if (!grid_built) build_grid();
    std::vector<int> out = grid.always;
    if (!grid.cells.empty()) {
      const int i = static_cast<int>(std::floor((p.x - grid.x0) / grid.cell));
      const int j = static_cast<int>(std::floor((p.y - grid.y0) / grid.cell));
      if (i >= 0 && i < grid.nx && j >= 0 && j < grid.ny) {
        const auto& c = grid.cells[static_cast<std::size_t>(i) * grid.ny + j];
        out.insert(out.end(), c.begin(), c.end());
      }
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
    // Which cycle each half-arc belongs to: outer cycles by face, holes by index.
    std::vector<int> outer_of_half(halves, -1), hole_of_half(halves, -1);
    for (std::size_t f = 0; f < d.faces.size(); ++f)
      for (const HalfArc& h : d.faces[f].boundaries.front()) outer_of_half[half_id(h.arc, h.forward)] = static_cast<int>(f);
    for (std::size_t k = 0; k < holes.size(); ++k)
      for (const HalfArc& h : holes[k]->arcs) hole_of_half[half_id(h.arc, h.forward)] = static_cast<int>(k);
    // Arc boxes in a uniform grid (rows by y, for horizontal rays).
    // A few holes (the usual case: the outer boundary of a weighted diagram) are cheaper to test
    // against every arc than to grid all arcs for.
    const bool scan_all = holes.size() <= 16;
    std::vector<std::array<double, 4>> box(scan_all ? 0 : d.arcs.size());
    double bx0 = INFINITY, by0 = INFINITY, bx1 = -INFINITY, by1 = -INFINITY;
    std::vector<int> unbounded_arcs;
    std::vector<char> is_unbounded(d.arcs.size(), 0);
    for (std::size_t a = 0; a < d.arcs.size(); ++a) {
      const ArcPathView& p = paths[a];
      if (!p.circle && (!std::isfinite(p.s0) || !std::isfinite(p.s1))) {
        unbounded_arcs.push_back(static_cast<int>(a));
        is_unbounded[a] = 1;
        continue;
      }
      if (scan_all) continue;
      std::array<double, 4> b = {INFINITY, INFINITY, -INFINITY, -INFINITY};
      auto grow = [&](Point q) {
        b = {std::min(b[0], q.x), std::min(b[1], q.y), std::max(b[2], q.x), std::max(b[3], q.y)};
      };
      if (p.circle) {
        grow(p.at(p.s0));
        grow(p.at(p.s1));
        for (int k = 0; k < 4; ++k) {
          double t = std::fmod(p.sense * (k * 0.5 * kPi - p.start_angle), kTwoPi);
          if (t < 0) t += kTwoPi;
          if (t >= p.s0 && t <= p.s1) grow(p.at(t));
        }
      } else {
        grow(p.at(p.s0));
        grow(p.at(p.s1));
      }
      box[a] = b;
      bx0 = std::min(bx0, b[0]), by0 = std::min(by0, b[1]), bx1 = std::max(bx1, b[2]), by1 = std::max(by1, b[3]);
    }
    // Grid bounds from the central 98% of node coordinates: far arcs of nearly tangent bisectors
    // would otherwise stretch the cells over the whole diagram (they land in the border cells).
    if (!scan_all && d.nodes.size() >= 100) {
      std::vector<double> nx, ny;
      for (const Node& n : d.nodes)
        if (std::isfinite(n.x) && std::isfinite(n.y)) nx.push_back(n.x), ny.push_back(n.y);
      if (nx.size() >= 100) {
        std::sort(nx.begin(), nx.end());
        std::sort(ny.begin(), ny.end());
        const std::size_t cut = nx.size() / 100;
        bx0 = nx[cut], bx1 = nx[nx.size() - 1 - cut], by0 = ny[cut], by1 = ny[ny.size() - 1 - cut];
      }
    }
    const int side = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(d.arcs.size()))), 1, 2048);
    const double cw = std::max((bx1 - bx0) / side, 1e-300), ch = std::max((by1 - by0) / side, 1e-300);
    std::vector<std::vector<int>> cell(scan_all ? 0 : static_cast<std::size_t>(side) * side);
    if (!scan_all && std::isfinite(bx0))
      for (std::size_t a = 0; a < d.arcs.size(); ++a) {
        if (is_unbounded[a]) continue;
        const auto& b = box[a];
        const int i0 = std::clamp(static_cast<int>((b[0] - bx0) / cw), 0, side - 1);
        const int i1 = std::clamp(static_cast<int>((b[2] - bx0) / cw), 0, side - 1);
        const int j0 = std::clamp(static_cast<int>((b[1] - by0) / ch), 0, side - 1);
        const int j1 = std::clamp(static_cast<int>((b[3] - by0) / ch), 0, side - 1);
        for (int i = i0; i <= i1; ++i)
          for (int j = j0; j <= j1; ++j) cell[static_cast<std::size_t>(j) * side + i].push_back(static_cast<int>(a));
      }
    // Crossings of the horizontal line y with an arc: (x, tangent y-component) pairs.
    auto crossings = [&](int a, double y, std::vector<std::pair<double, double>>& out) {
      const ArcPathView& p = paths[a];
      out.clear();
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
          if ((s > p.s0 && s < p.s1) || full) out.emplace_back(x, p.tangent(s).y);
        }
      } else if (p.uy != 0) {
        const double s = (y - p.oy) / p.uy;
        if (s > p.s0 && s < p.s1) out.emplace_back(p.ox + s * p.ux, p.uy);
      }
    };
    std::vector<std::pair<double, double>> xs;
    std::vector<int> stamp(d.arcs.size(), -1);
    if (scan_all)  // the extent for eps_x from the nodes (no arc boxes were made)
      for (const Node& n : d.nodes)
        if (std::isfinite(n.x) && std::isfinite(n.y))
          bx0 = std::min(bx0, n.x), bx1 = std::max(bx1, n.x), by0 = std::min(by0, n.y), by1 = std::max(by1, n.y);
    const double eps_x = std::isfinite(bx0) ? 1e-12 * std::max(bx1 - bx0, by1 - by0) : 0.0;
    for (std::size_t k = 0; k < holes.size(); ++k) {
      // Rightmost point of the hole.
      Point right{-INFINITY, 0};
      for (const HalfArc& h : holes[k]->arcs) {
        const ArcPathView& p = paths[h.arc];
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
      if (!std::isfinite(right.x) || (!scan_all && !std::isfinite(bx0))) continue;
      double best_x = INFINITY, best_ty = 0;
      int best_arc = -1;
      bool ambiguous = false;
      auto test_arc = [&](int a) {
        crossings(a, right.y, xs);
        for (auto [x, ty] : xs) {
          if (x <= right.x + eps_x) continue;
          if (std::abs(x - best_x) <= eps_x) ambiguous = true;
          if (x < best_x) best_x = x, best_ty = ty, best_arc = a, ambiguous = false;
        }
      };
      for (int a : unbounded_arcs) test_arc(a);
      if (scan_all)
        for (std::size_t a = 0; a < d.arcs.size(); ++a)
          if (!is_unbounded[a]) test_arc(static_cast<int>(a));
      const int j = scan_all ? 0 : std::clamp(static_cast<int>((right.y - by0) / ch), 0, side - 1);
      for (int i = scan_all ? side : std::clamp(static_cast<int>((right.x - bx0) / cw), 0, side - 1); i < side; ++i) {
        if (i > 0 && best_x < bx0 + i * cw) break;  // the nearest hit is left of this cell
        for (int a : cell[static_cast<std::size_t>(j) * side + i]) {
          if (stamp[a] == static_cast<int>(k)) continue;  // an arc spans several cells
          stamp[a] = static_cast<int>(k);
          test_arc(a);
        }
      }
      if (best_arc < 0) {
        ray_face[k] = unbounded_arcs.empty() ? -1 : -2;
        continue;
      }
      if (ambiguous || std::abs(best_ty) < 1e-12) continue;  // through a node, or tangent: fall back
      // The half-arc facing -x (the ray's origin) on its left: tangent pointing up.
      const int hit = half_id(best_arc, best_ty > 0);
      if (outer_of_half[hit] >= 0) ray_face[k] = outer_of_half[hit];
      else if (hole_of_half[hit] >= 0 && hole_of_half[hit] != static_cast<int>(k)) ray_face[k] = -3 - hole_of_half[hit];
    }
    // Resolve chains of holes (-3 - other) to faces.
    for (std::size_t k = 0; k < holes.size(); ++k) {
      int v = ray_face[k], steps = 0;
      while (v <= -3 && steps++ <= static_cast<int>(holes.size())) v = ray_face[-3 - v];
      ray_face[k] = v <= -3 ? -2 : v;
    }
  }
  for (std::size_t hk = 0; hk < holes.size(); ++hk) {
    const Cycle* hole = holes[hk];
    if (ray_face[hk] != -2) {
      int target = ray_face[hk];
      if (target < 0) target = implicit_face_of(hole->site);
      d.faces[target].boundaries.push_back(hole->arcs);
      continue;
    }
    const HalfArc first = hole->arcs.front();
    const ArcPathView path = arc_path(d.arcs[first.arc], d.nodes);
    const double mid = std::isfinite(path.s0) && std::isfinite(path.s1) ? 0.5 * (path.s0 + path.s1)
                       : std::isfinite(path.s0)                          ? path.s0 + 1.0
                       : std::isfinite(path.s1)                          ? path.s1 - 1.0
                                                                         : 0.0;
    const Point p = path.at(mid);
    int target = -1;
    std::vector<int> across;
    for (const HalfArc& h : hole->arcs) across.push_back(outer_face_of_half[half_id(h.arc, !h.forward)]);
    for (int f : candidate_faces(p)) {
      if (d.faces[f].site != (by_sites ? hole->site : kNone)) continue;
      if (f >= static_cast<int>(outer_area.size())) continue;  // hole-only faces have no outer
      if (std::find(across.begin(), across.end(), f) != across.end()) continue;
      // Innermost containing outer cycle (smallest area) wins.
      if (contains_with(d, d.faces[f].boundaries.front(), p,
                        [&](int arc) -> const ArcPathView& { return paths[arc]; }) &&
          (target < 0 || outer_area[f] < outer_area[target]))
        target = f;
    }
    if (target < 0) {
      target = implicit_face_of(hole->site);
    }
    d.faces[target].boundaries.push_back(hole->arcs);
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
