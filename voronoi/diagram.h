// covmap::voronoi::Diagram — the plain data type every covmap algorithm reads or writes.
//
// Contract: a Diagram is a planar circular-arc graph over a list of weighted sites. It holds no
// algorithm state; engines fill it, checkers and writers read it. Every arc lies on the
// multiplicatively weighted bisector of its two sites (an Apollonius circle, or a straight line for
// equal weights), except frame arcs, which follow a clipping boundary and have a kNone site on
// their outer side. Indices are plain ints into the vectors below; kNone marks "no such thing"
// (an unbounded end, the outside of the frame).
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace covmap::voronoi {

inline constexpr int kNone = -1;

struct Point {
  double x = 0.0;
  double y = 0.0;
};

// A sensor: distance to it is Euclidean distance divided by weight.
struct Site {
  std::string id;
  double x = 0.0;
  double y = 0.0;
  double weight = 1.0;
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
// true (clockwise otherwise); from == to == kNone is the full circle. Line arcs run along +d; a
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

// A connected component of one site's region. Each boundary is a closed cycle of half-arcs with the
// face on its left; for unbounded faces a cycle may pass through infinity (between an arc whose end
// is kNone and the next arc, whose start is kNone). The first boundary is the outer one for
// bounded faces; further boundaries are holes. An orphan face does not contain its own site.
struct Face {
  int site = kNone;
  bool bounded = true;
  bool orphan = false;
  std::vector<std::vector<HalfArc>> boundaries;
};

struct Diagram {
  std::vector<Site> sites;
  std::vector<Node> nodes;
  std::vector<Arc> arcs;
  std::vector<Face> faces;
  // The clipping polygon (counter-clockwise) when the diagram was clipped, else empty.
  std::vector<Point> clip;
};

}  // namespace covmap::voronoi
