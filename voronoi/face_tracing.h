// The stages of trace_faces() (faces.cpp) and the plain data they pass between them. Internal to the
// voronoi library: not a public header (voronoi/CMakeLists.txt).
//
// In the order trace_faces() runs them:
//   per-arc geometry     tracing_geometry.cpp   departure angles and curvatures, segment areas, boxes
//   continuations        continuations.cpp      the half-arc after each one at the node where it ends
//   cycle walk           cycle_walk.cpp         the closed cycles of the continuations
//   cycle orientation    cycle_orientation.cpp  signed areas: outer cycles and holes
//   outer faces          outer_faces.cpp        one face per outer cycle, the diagram's half-arcs
//   hole rays            hole_rays.cpp          (by geometry) a hole's face from a ray to +x
//   hole placement       hole_placement.cpp     each hole into its face, by ray or by containment
//   face cycles          outer_faces.cpp        each face's cycles into Diagram::cycles
//   face index           face_index.cpp         per half-arc, its face and its successor
// Small helpers used in the hot loops are inline here, so that every file above inlines them.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <span>
#include <unordered_map>
#include <vector>

#include "core/box.h"
#include "core/diagram.h"
#include "core/large_buffer.h"
#include "voronoi/arc_path.h"
#include "voronoi/faces.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi::tracing {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2 * kPi;
// Direction of the containment test ray: any angle works; an irrational-looking one avoids rays
// along the axes, where hand-made and grid inputs put their nodes.
inline constexpr double kRayAngle = 0.7391;

// ---- Half-arcs ----

struct HalfInfo {
  int site = kNone;
  int start = kNone;  // node, kNone at infinity
  int end = kNone;
};

inline int half_id(int arc, bool forward) { return 2 * arc + (forward ? 0 : 1); }
inline HalfArc half_of(int id) { return {id / 2, id % 2 == 0}; }

inline HalfInfo info(const Diagram& d, int id) {
  const Arc& a = d.arcs[id / 2];
  const bool fwd = id % 2 == 0;
  return {fwd ? a.left_site : a.right_site, fwd ? a.from : a.to, fwd ? a.to : a.from};
}

// The region a half-arc bounds: its site, or (by geometry) one common label, so that every
// continuation at a node is chosen by angle.
inline int label(const Diagram& d, bool by_sites, int h) { return by_sites ? info(d, h).site : 0; }

// A point at infinity: the direction angle, and the offset that orders parallel arcs.
struct AtInfinity {
  double angle = 0.0;
  double offset = 0.0;
};

inline AtInfinity infinity_key(const Diagram& d, int id, bool leaving) {
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

inline bool key_less(const AtInfinity& a, const AtInfinity& b) {
  if (std::fabs(a.angle - b.angle) > tolerance::kParallelAngle) return a.angle < b.angle;
  return a.offset < b.offset;
}

// Counter-clockwise angular distance from a to b in [0, 2π).
inline double ccw_distance(double a, double b) {
  double x = b - a;
  while (x < 0) x += kTwoPi;
  while (x >= kTwoPi) x -= kTwoPi;
  return x;
}

// ---- Per-arc geometry (tracing_geometry.cpp) ----

// The direction of travel of half-arc h where it leaves its start node (not normalized): a line's
// direction, or a circle's radius at the node turned by +90° (counter-clockwise travel) or -90°.
// Read afresh from the arc and its node where pseudo-angles tie (continuations.cpp): near the
// wrap of the pseudo-angle a direction just below +x rounds to kPseudoTurn itself.
inline Point departure_vector(const Arc& arc, const Node& start, bool forward) {
  Point v;
  if (const Circle* c = std::get_if<Circle>(&arc.curve)) {
    const double ax = start.x - c->cx, ay = start.y - c->cy;
    v = arc.ccw ? Point{-ay, ax} : Point{ay, -ax};
  } else {
    const Line& l = std::get<Line>(arc.curve);
    v = {l.dx, l.dy};
  }
  return forward ? v : Point{-v.x, -v.y};
}


// Boxes kept per arc in single precision, rounded outward (half the memory of doubles; a box only
// preselects). Coordinates beyond float range become infinite: such a box is treated as unbounded.
using FloatBox = std::array<float, 4>;

inline Box to_double(const FloatBox& f) { return {f[0], f[1], f[2], f[3]}; }  // FloatBox: xmin, ymin, xmax, ymax

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

TracingGeometry tracing_geometry(const Diagram& d, bool with_boxes);

// The box holding the central 98 % of the nodes in each coordinate: far arcs of nearly tangent
// bisectors would otherwise stretch a grid's cells over the whole diagram.
Box central_box(const std::vector<Node>& nodes);

// ---- Continuations (continuations.cpp) ----

// Per half-arc, the half-arc following it around its face (-1: none).
LargeVector<int> continuations(const Diagram& d, bool by_sites, const TracingGeometry& geometry);

// ---- Cycles (cycle_walk.cpp, cycle_orientation.cpp) ----

struct Cycle {
  int site = kNone;
  int begin = 0, end = 0;  // range in cycle_halves
  bool through_infinity = false;
  double area2 = 0.0;  // twice the signed area (closed cycles)
};

// Closed cycles, stored one after the other in `cycle_halves` (no vector per cycle: a graph of
// 10^6 faces would spend more time allocating than tracing).
struct CycleSet {
  LargeVector<Cycle> cycles;
  LargeVector<int> cycle_halves;
  std::span<const int> halves_of(const Cycle& c) const {
    return std::span<const int>(cycle_halves.data() + c.begin, static_cast<std::size_t>(c.end - c.begin));
  }
};

CycleSet walk_cycles(const Diagram& d, bool by_sites, const LargeVector<int>& next_half);

// Sets every cycle's area2 and through_infinity; returns per half-arc its cycle (-1: none).
LargeVector<int> orient_cycles(const Diagram& d, const TracingGeometry& geometry, CycleSet& cs);

// ---- Faces (outer_faces.cpp, hole_rays.cpp, hole_placement.cpp, face_index.cpp) ----

// The faces being made and what placing holes needs to know about them.
// The cycles' half-arcs are already in Diagram::half_arcs (in the order of cycle_halves); which
// cycles each face has is written to Diagram::cycles once every hole is placed (store_face_cycles).
// Per label (a site, kNone outside a clip frame; 0 for every face tracing by geometry), the faces
// made for it, in the order they were made: lists threaded through the face ids, so a million
// sites cost no allocation each (as a hash map of vectors would).
class FacesOfSite {
 public:
  FacesOfSite() = default;
  // Labels from kNone to sites - 1.
  explicit FacesOfSite(std::size_t sites) : head_(sites + 1, -1), tail_(sites + 1, -1) {}
  void add(int site, int face) {
    if (next_.size() <= static_cast<std::size_t>(face)) next_.resize(face + 1, -1);
    int& tail = tail_[site + 1];
    if (tail < 0) {
      head_[site + 1] = face;
      sites_.push_back(site);
    } else {
      next_[tail] = face;
    }
    tail = face;
  }
  bool empty(int site) const { return head_[site + 1] < 0; }
  bool single(int site) const { return !empty(site) && head_[site + 1] == tail_[site + 1]; }
  int front(int site) const { return head_[site + 1]; }
  template <class F>
  void for_each(int site, F&& f) const {
    for (int face = head_[site + 1]; face >= 0; face = next_[face]) f(face);
  }
  // The labels with faces, in the order of their first face.
  const std::vector<int>& sites() const { return sites_; }

 private:
  LargeVector<int> head_, tail_, next_;
  std::vector<int> sites_;
};

struct FaceAssembly {
  FacesOfSite faces_of_site;
  std::vector<int> holes;  // cycle indices
  LargeVector<int> face_of_cycle, hole_of_cycle;
  LargeVector<double> outer_area;  // per face: |area| of its outer cycle (∞ when unbounded)
  LargeVector<CycleRange> outer_cycle;  // per face: its outer cycle in Diagram::half_arcs
  LargeVector<char> has_outer;     // per face made from an outer cycle
  std::map<int, int> implicit_face;  // site -> its unbounded face without outer cycle
};

// The outer cycle of face f (f < fa.outer_cycle.size(): a face made from an outer cycle).
inline std::span<const HalfArc> outer_cycle_of(const Diagram& d, const FaceAssembly& fa, int f) {
  return cycle_half_arcs(d, fa.outer_cycle[f]);
}

// The half-arcs of all cycles into Diagram::half_arcs, and one face per outer cycle
// (counter-clockwise or through infinity); clockwise cycles are listed as holes.
FaceAssembly outer_faces(Diagram& d, bool by_sites, const CycleSet& cs);

// The unbounded component of a site without lines has no outer cycle, only holes: one face per
// site (per graph when tracing by geometry), made on first use.
int implicit_face_of(Diagram& d, bool by_sites, FaceAssembly& fa, int site);

// Per hole, its face as a ray from it finds it (tracing by geometry): face, -1 unbounded, -2
// undecided (always, tracing by sites).
std::vector<int> hole_ray_faces(const Diagram& d, bool by_sites, const TracingGeometry& geometry, const CycleSet& cs,
                                const LargeVector<int>& cycle_of_half, const FaceAssembly& fa);

// Each hole into its face: the one its ray found, else the innermost outer cycle of its site that
// contains it, else its site's unbounded face.
void place_holes(Diagram& d, bool by_sites, const CycleSet& cs, const LargeVector<int>& cycle_of_half,
                 const std::vector<int>& ray_face, FaceAssembly& fa);

// Each face's cycles into Diagram::cycles: its outer cycle first, then its holes in the order
// place_holes() placed them. Faces added later (add_face) have none.
void store_face_cycles(Diagram& d, const CycleSet& cs, const FaceAssembly& fa);

void fill_face_index(FaceIndex& index, LargeVector<int> next_half, const LargeVector<int>& cycle_of_half,
                     const LargeVector<int>& face_of_cycle);

// ---- Containment ----

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
          const double s = path.param_of({p.x + t * dir.x, p.y + t * dir.y});
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

}  // namespace covmap::voronoi::tracing
