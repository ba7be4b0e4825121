// covmap::Diagram — the plain data type every covmap algorithm reads or writes.
//
// Contract: a Diagram is a planar circular-arc graph over a list of weighted sites. It holds no
// algorithm state; engines fill it, checkers and writers read it. Every arc lies on the
// multiplicatively weighted bisector of its two sites (an Apollonius circle, or a straight line for
// equal weights), except frame arcs, which follow a clipping boundary and have a kNone site on
// their outer side. Indices are plain ints into the vectors below; kNone marks "no such thing"
// (an unbounded end, the outside of the frame).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace covmap {

inline constexpr int kNone = -1;

struct Point {
  double x = 0.0;
  double y = 0.0;
};

// A sensor: distance to it is Euclidean distance divided by weight. The id identifies it (unique in
// a list); the name is only for people (labels in pictures), empty when the input gave none.
struct Site {
  std::string id;
  double x = 0.0;
  double y = 0.0;
  double weight = 1.0;
  std::string name{};  // initialized so that {id, x, y, weight} stays a complete initializer
};

struct Node {
  double x = 0.0;
  double y = 0.0;
};

struct Circle {
  double cx = 0.0;
  double cy = 0.0;
  double r = 0.0;
};

// The line through (x, y) with direction (dx, dy); arcs on it run along +d.
struct Line {
  double x = 0.0;
  double y = 0.0;
  double dx = 1.0;
  double dy = 0.0;
};

using Curve = std::variant<Circle, Line>;

// One arc of the graph. Circle arcs run from -> to counter-clockwise around the centre when ccw is
// true (clockwise otherwise). Their extent is decided by the end node indices (core/arc_sweep.h,
// read the same way by every algorithm and by the checker): from == to == kNone is the full circle;
// from == to is a loop once round the circle from that node; distinct nodes bound the angle swept
// from `from` to `to`, in [0, 2π): two distinct nodes at the same angle bound an arc of length
// zero, never a full circle. Line arcs run along +d; a
// kNone end is at infinity (both kNone: the whole line). left_site / right_site are the sites on
// the left and right of the arc's direction of travel; a frame arc has kNone on the outer side.
struct Arc {
  int from = kNone;
  int to = kNone;
  Curve curve = Circle{};
  bool ccw = true;
  int left_site = kNone;
  int right_site = kNone;
  bool frame = false;  // true: part of the clipping boundary, not a bisector
};

// An arc traversed in a face boundary: forward = from -> to.
struct HalfArc {
  int arc = kNone;
  bool forward = true;
};

// The boundary cycles of all faces, stored compressed in the Diagram (no vector per face: a
// million faces would otherwise cost two million small allocations): Diagram::cycles lists the
// cycles of face 0, then those of face 1, …; each cycle is a range of Diagram::half_arcs. Read them
// with face_cycles(); make faces with add_face() and add_cycle().
struct CycleRange {
  int begin = 0;  // half-arcs [begin, end) of Diagram::half_arcs
  int end = 0;
};

// A connected component of one site's region. Each boundary is a closed cycle of half-arcs with the
// face on its left; for unbounded faces a cycle may pass through infinity (between an arc whose end
// is kNone and the next arc, whose start is kNone). The first boundary is the outer one for
// bounded faces; further boundaries are holes. An orphan face does not contain its own site.
struct Face {
  int site = kNone;
  bool bounded = true;
  bool orphan = false;
  int cycles_begin = 0;  // its boundaries: cycles [cycles_begin, cycles_end) of Diagram::cycles
  int cycles_end = 0;
};

struct Diagram {
  std::vector<Site> sites;
  std::vector<Node> nodes;
  std::vector<Arc> arcs;
  std::vector<Face> faces;
  std::vector<CycleRange> cycles;  // the faces' boundary cycles, face after face
  std::vector<HalfArc> half_arcs;  // the cycles' half-arcs (in any order: each cycle names its range)
  // The clipping polygon (counter-clockwise) when the diagram was clipped, else empty.
  std::vector<Point> clip;
};

// ---- Reading faces ----

// One boundary cycle as a span of half-arcs.
inline std::span<const HalfArc> cycle_half_arcs(const Diagram& d, const CycleRange& c) {
  return {d.half_arcs.data() + c.begin, static_cast<std::size_t>(c.end - c.begin)};
}

// The boundary cycles of one face, read like a vector of spans of half-arcs:
// `for (auto cycle : face_cycles(d, face))`, `face_cycles(d, f).front()`, `[k]`, `size()`.
class FaceCycles {
 public:
  using Cycle = std::span<const HalfArc>;

  FaceCycles(const Diagram& d, const Face& f) : d_(&d), begin_(f.cycles_begin), end_(f.cycles_end) {}

  std::size_t size() const { return static_cast<std::size_t>(end_ - begin_); }
  bool empty() const { return end_ == begin_; }
  Cycle operator[](std::size_t k) const { return cycle_half_arcs(*d_, d_->cycles[begin_ + k]); }
  Cycle front() const { return (*this)[0]; }
  Cycle back() const { return (*this)[size() - 1]; }

  class const_iterator {
   public:
    using value_type = Cycle;
    using difference_type = std::ptrdiff_t;
    const_iterator() = default;
    const_iterator(const Diagram* d, int k) : d_(d), k_(k) {}
    Cycle operator*() const { return cycle_half_arcs(*d_, d_->cycles[k_]); }
    const_iterator& operator++() {
      ++k_;
      return *this;
    }
    const_iterator operator++(int) {
      const_iterator old = *this;
      ++k_;
      return old;
    }
    bool operator==(const const_iterator& o) const { return k_ == o.k_; }

   private:
    const Diagram* d_ = nullptr;
    int k_ = 0;
  };
  const_iterator begin() const { return {d_, begin_}; }
  const_iterator end() const { return {d_, end_}; }

 private:
  const Diagram* d_;
  int begin_, end_;
};

inline FaceCycles face_cycles(const Diagram& d, const Face& f) { return {d, f}; }
inline FaceCycles face_cycles(const Diagram& d, int f) { return {d, d.faces[f]}; }

// ---- Making faces ----
// Faces are appended one after the other, each followed by its cycles, so that the cycles of each
// face stay together in Diagram::cycles.

// Removes every face with its cycles.
inline void clear_faces(Diagram& d) {
  d.faces.clear();
  d.cycles.clear();
  d.half_arcs.clear();
}

// Appends a face without cycles (its cycle range is set here); returns its index.
inline int add_face(Diagram& d, Face face) {
  face.cycles_begin = face.cycles_end = static_cast<int>(d.cycles.size());
  d.faces.push_back(face);
  return static_cast<int>(d.faces.size()) - 1;
}

// Appends a copy of `cycle` to the last face.
inline void add_cycle(Diagram& d, std::span<const HalfArc> cycle) {
  const int begin = static_cast<int>(d.half_arcs.size());
  d.half_arcs.insert(d.half_arcs.end(), cycle.begin(), cycle.end());
  d.cycles.push_back({begin, static_cast<int>(d.half_arcs.size())});
  d.faces.back().cycles_end = static_cast<int>(d.cycles.size());
}

// Appends a face with the given cycles (hand-made diagrams): add_face(d, {0, true, false}, {{{0, true}}}).
inline int add_face(Diagram& d, Face face, std::initializer_list<std::vector<HalfArc>> cycles) {
  const int f = add_face(d, face);
  for (const auto& c : cycles) add_cycle(d, c);
  return f;
}

}  // namespace covmap
