// Diagrams built by hand from closed forms, for testing the checker. Nothing here calls an engine
// or the checker: every node, curve and side is derived in the comments (and, for the weighted
// lens, computed in place by a textbook circle intersection that the checker does not share).
#pragma once

#include <cmath>
#include <utility>

#include "core/diagram.h"

namespace covmap::check::testing {

inline Site site(double x, double y, double w = 1.0) { return Site{"", x, y, w}; }

inline Arc line_arc(int from, int to, Line line, int left, int right) {
  Arc a;
  a.from = from;
  a.to = to;
  a.curve = line;
  a.left_site = left;
  a.right_site = right;
  return a;
}

inline Arc circle_arc(int from, int to, Circle circle, bool ccw, int left, int right) {
  Arc a;
  a.from = from;
  a.to = to;
  a.curve = circle;
  a.ccw = ccw;
  a.left_site = left;
  a.right_site = right;
  return a;
}

// (a) Sites (0,0) and (2,0), equal weights: the bisector is the line x = 1. Travelling up (+y) the
// left side is -x, where site 0 is. Faces: site 0 on the left of the arc, site 1 on its right.
inline Diagram two_equal_sites() {
  Diagram d;
  d.sites = {site(0, 0), site(2, 0)};
  d.arcs = {line_arc(kNone, kNone, Line{1, 0, 0, 1}, 0, 1)};
  add_face(d, {0, false, false}, {{HalfArc{0, true}}});
  add_face(d, {1, false, false}, {{HalfArc{0, false}}});
  return d;
}

// (b) A = (0,0) w 1, B = (3,0) w 2. Apollonius circle: c = A + wA^2 (B - A) / ((wA - wB)(wA + wB))
// = (3,0) / (-3) = (-1, 0); r = wA wB |B - A| / |wA^2 - wB^2| = 6 / 3 = 2. Check: (1,0) is 1/1 from
// A and 2/2 from B; (-3,0) is 3/1 and 6/2. The lighter site A owns the disc, which is on the left
// of counter-clockwise travel. Faces: A's disc (ccw, on the left), B's outside (the circle
// reversed).
inline Diagram two_weighted_sites() {
  Diagram d;
  d.sites = {site(0, 0, 1), site(3, 0, 2)};
  d.arcs = {circle_arc(kNone, kNone, Circle{-1, 0, 2}, true, 0, 1)};
  add_face(d, {0, true, false}, {{HalfArc{0, true}}});
  add_face(d, {1, false, false}, {{HalfArc{0, false}}});
  return d;
}

// (b') Weights equal to 14 digits: s0 (0,0) weight 1, s1 (0.7,0.3) weight 1 + 1.3e-14. The bisector
// is a circle of radius ~3e13 passing between the sites with s0 inside, centre and radius from
// the closed form (docs/NUMERICS.md, 'Apollonius centre': a correction added to s0). Its numbers
// are only known to ~1e-2.
inline Diagram nearly_equal_weights() {
  const double wj = 1.0 + 1.3e-14, dx = 0.7, dy = 0.3;
  const double k = 1.0 / ((1.0 - wj) * (1.0 + wj));
  Diagram d;
  d.sites = {site(0, 0, 1), site(dx, dy, wj)};
  const double r = wj * std::hypot(dx, dy) * std::abs(k);
  d.arcs = {circle_arc(kNone, kNone, Circle{k * dx, k * dy, r}, true, 0, 1)};
  add_face(d, {0, true, false}, {{HalfArc{0, true}}});
  add_face(d, {1, false, false}, {{HalfArc{0, false}}});
  return d;
}

// (c) Acute triangle s0 (0,0), s1 (4,0), s2 (1,3), equal weights. Circumcentre: x = 2 (bisector of
// s0 s1); |p|^2 = |p - s2|^2 gives 2x + 6y = 10, so y = 1: node (2,1), at distance sqrt(5) from
// all. Each ray leaves the node through the midpoint of the opposite edge:
//   s0|s1 through (2,0): direction (0,-1); left normal (1,0) points at s1.
//   s0|s2 through (0.5,1.5): direction (-3,1); left normal (-1,-3) points at s0.
//   s1|s2 through (2.5,1.5): direction (1,1); left normal (-1,1) points at s2.
inline Diagram triangle() {
  Diagram d;
  d.sites = {site(0, 0), site(4, 0), site(1, 3)};
  d.nodes = {Node{2, 1}};
  d.arcs = {line_arc(0, kNone, Line{2, 1, 0, -1}, 1, 0),
            line_arc(0, kNone, Line{2, 1, -3, 1}, 0, 2),
            line_arc(0, kNone, Line{2, 1, 1, 1}, 2, 1)};
  return d;
}

// (d) Square s0 (0,0), s1 (2,0), s2 (2,2), s3 (0,2), equal weights: a degree-4 node at (1,1) and
// four axis rays; the left site of each is the next site counter-clockwise.
inline Diagram square() {
  Diagram d;
  d.sites = {site(0, 0), site(2, 0), site(2, 2), site(0, 2)};
  d.nodes = {Node{1, 1}};
  d.arcs = {line_arc(0, kNone, Line{1, 1, 0, -1}, 1, 0), line_arc(0, kNone, Line{1, 1, 1, 0}, 2, 1),
            line_arc(0, kNone, Line{1, 1, 0, 1}, 3, 2),
            line_arc(0, kNone, Line{1, 1, -1, 0}, 0, 3)};
  return d;
}

// Rhombus s0 (0,-1), s1 (0,1), s2 (-3,0), s3 (3,0), equal weights. Nodes: circumcentres of s0 s1 s2
// and s0 s1 s3, on y = 0 with x^2 + 1 = (x + 3)^2, so L = (-4/3, 0) and R = (4/3, 0). Arc 0 is the
// segment L -> R along +x (s1 above, on the left). The rays leave through edge midpoints:
//   L, s2|s1 via (-1.5, 0.5): direction (-1,3), left normal (-3,-1) points at s2;
//   L, s0|s2 via (-1.5,-0.5): direction (-1,-3), left normal (3,-1) points at s0;
//   R, s1|s3 via (1.5, 0.5): direction (1,3), left normal (-3,1) points at s1;
//   R, s3|s0 via (1.5,-0.5): direction (1,-3), left normal (3,1) points at s3.
inline Diagram rhombus() {
  Diagram d;
  d.sites = {site(0, -1), site(0, 1), site(-3, 0), site(3, 0)};
  const double k = 4.0 / 3.0;
  d.nodes = {Node{-k, 0}, Node{k, 0}};
  d.arcs = {line_arc(0, 1, Line{-k, 0, 1, 0}, 1, 0), line_arc(0, kNone, Line{-k, 0, -1, 3}, 2, 1),
            line_arc(0, kNone, Line{-k, 0, -1, -3}, 0, 2),
            line_arc(1, kNone, Line{k, 0, 1, 3}, 1, 3),
            line_arc(1, kNone, Line{k, 0, 1, -3}, 3, 0)};
  // Site 1's face (above): the segment forward, R's upper ray forward, then through infinity to
  // L's upper ray backwards. Its arcs name site 1 on the left, left, right respectively.
  add_face(d, {1, false, false}, {{HalfArc{0, true}, HalfArc{3, true}, HalfArc{1, false}}});
  return d;
}

// Two points where circles (c1, r1) and (c2, r2) meet, by the textbook radical-line formula.
inline std::pair<Point, Point> textbook_circle_intersection(Point c1, double r1, Point c2,
                                                            double r2) {
  const double dx = c2.x - c1.x, dy = c2.y - c1.y, dist = std::hypot(dx, dy);
  const double a = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist);
  const double h = std::sqrt(r1 * r1 - a * a);
  const Point m{c1.x + a * dx / dist, c1.y + a * dy / dist};
  return {Point{m.x - h * dy / dist, m.y + h * dx / dist},
          Point{m.x + h * dy / dist, m.y - h * dx / dist}};
}

// (e) A = (0,0) w 1, B = (4,0) w 2, C = (0,4) w 2. Bisector A|B: c = (4,0)/((1-2)(1+2)) = (-4/3,
// 0), r = 2*4/3 = 8/3; A|C: (0,-4/3), r = 8/3; B|C (equal weights): the line y = x. A, the
// lightest, owns the lens where both discs overlap; B and C split the rest along y = x. The nodes
// are the two intersections of the A|B and A|C circles (found on y = x: 3t^2 + 4t - 8 = 0, t = (-2
// +- 2 sqrt 7)/3), N1 upper right (node 0), N2 lower left (node 1). Seen from the A|B centre, N2 is
// at about -114 degrees and N1 at 24, and the lens side of that circle is around -45: so the A|B
// arc runs counter-clockwise N2 -> N1 with A (inside) on the left. Likewise A|C runs
// counter-clockwise N1 (66 degrees) -> N2 (204 degrees) through 135. Rays on y = x along +(1,1)
// have C on the left.
inline Diagram weighted_lens() {
  Diagram d;
  d.sites = {site(0, 0, 1), site(4, 0, 2), site(0, 4, 2)};
  const Point cab{-4.0 / 3, 0}, cac{0, -4.0 / 3};
  const double r = 8.0 / 3;
  auto [p, q] = textbook_circle_intersection(cab, r, cac, r);
  if (p.x + p.y < q.x + q.y) std::swap(p, q);
  d.nodes = {Node{p.x, p.y}, Node{q.x, q.y}};
  d.arcs = {circle_arc(1, 0, Circle{cab.x, cab.y, r}, true, 0, 1),
            circle_arc(0, 1, Circle{cac.x, cac.y, r}, true, 0, 2),
            line_arc(0, kNone, Line{p.x, p.y, 1, 1}, 2, 1),
            line_arc(kNone, 1, Line{q.x, q.y, 1, 1}, 2, 1)};
  return d;
}

// The Apollonius circle of a and b (unequal weights), from the closed form
// c = s_a + w_a^2 (s_b - s_a) / (w_a^2 - w_b^2), r = w_a w_b |s_b - s_a| / |w_a^2 - w_b^2|.
inline Circle apollonius(const Site& a, const Site& b) {
  const double k = a.weight * a.weight / (a.weight * a.weight - b.weight * b.weight);
  return Circle{a.x + k * (b.x - a.x), a.y + k * (b.y - a.y),
                a.weight * b.weight * std::hypot(b.x - a.x, b.y - a.y) /
                    std::abs(a.weight * a.weight - b.weight * b.weight)};
}

// Three sites with three different weights: A (0,0) w 1, B (4,0) w 2, C (0,4) w 3. All three
// bisector circles pass through the same two points (equidistant from all three sites), found as
// the intersections of A|B and A|C. The diagram is a theta: one arc of each circle between those
// two nodes. Of a circle's two arcs the diagram keeps the one whose middle is farther from the
// third site than from its own two, decided here by direct distance comparisons. The lighter site
// owns the inside of each circle, which is on the left of counter-clockwise travel. With
// use_wrong_arc, the B|C arc is replaced by the other arc of its circle.
inline Diagram weighted_theta(bool use_wrong_arc = false) {
  Diagram d;
  d.sites = {site(0, 0, 1), site(4, 0, 2), site(0, 4, 3)};
  const Circle ab = apollonius(d.sites[0], d.sites[1]), ac = apollonius(d.sites[0], d.sites[2]);
  const auto [n0, n1] = textbook_circle_intersection({ab.cx, ab.cy}, ab.r, {ac.cx, ac.cy}, ac.r);
  d.nodes = {Node{n0.x, n0.y}, Node{n1.x, n1.y}};
  const auto wd = [&](int s, Point p) {
    return std::hypot(p.x - d.sites[s].x, p.y - d.sites[s].y) / d.sites[s].weight;
  };
  const int pairs[3][3] = {{0, 1, 2}, {0, 2, 1}, {1, 2, 0}};  // lighter, heavier, third
  for (const auto& [i, j, k] : pairs) {
    const Circle c = apollonius(d.sites[i], d.sites[j]);
    const double a0 = std::atan2(n0.y - c.cy, n0.x - c.cx),
                 a1 = std::atan2(n1.y - c.cy, n1.x - c.cx);
    double sweep = std::fmod(a1 - a0 + 4 * M_PI, 2 * M_PI);  // counter-clockwise n0 -> n1
    const double mid = a0 + 0.5 * sweep;
    const Point m{c.cx + c.r * std::cos(mid), c.cy + c.r * std::sin(mid)};
    bool n0_to_n1 = wd(k, m) > std::max(wd(i, m), wd(j, m));
    if (use_wrong_arc && k == 0) n0_to_n1 = !n0_to_n1;
    d.arcs.push_back(n0_to_n1 ? circle_arc(0, 1, c, true, i, j) : circle_arc(1, 0, c, true, i, j));
  }
  return d;
}

// (a) clipped to the box [-1,3] x [-1,1] (counter-clockwise). Nodes: 0 (1,-1) and 1 (1,1) where the
// bisector x = 1 meets the frame, then the corners 2 (3,-1), 3 (3,1), 4 (-1,1), 5 (-1,-1). Frame
// arcs run counter-clockwise along the clip polygon, so the inside (the site) is on their left.
inline Diagram clipped_two_sites() {
  Diagram d;
  d.sites = {site(0, 0), site(2, 0)};
  d.clip = {Point{-1, -1}, Point{3, -1}, Point{3, 1}, Point{-1, 1}};
  d.nodes = {Node{1, -1}, Node{1, 1}, Node{3, -1}, Node{3, 1}, Node{-1, 1}, Node{-1, -1}};
  d.arcs = {line_arc(0, 1, Line{1, -1, 0, 1}, 0, 1)};
  const auto frame = [](int from, int to, Line l, int inside) {
    Arc a = line_arc(from, to, l, inside, kNone);
    a.frame = true;
    return a;
  };
  d.arcs.push_back(frame(0, 2, Line{1, -1, 1, 0}, 1));
  d.arcs.push_back(frame(2, 3, Line{3, -1, 0, 1}, 1));
  d.arcs.push_back(frame(3, 1, Line{3, 1, -1, 0}, 1));
  d.arcs.push_back(frame(1, 4, Line{1, 1, -1, 0}, 0));
  d.arcs.push_back(frame(4, 5, Line{-1, 1, 0, -1}, 0));
  d.arcs.push_back(frame(5, 0, Line{-1, -1, 1, 0}, 0));
  return d;
}

// A k x k lattice of equal-weight sites at integer points (k >= 2): the cells are unit squares
// around the sites, with degree-4 nodes at the half-integer points (i + 0.5, j + 0.5), 0 <= i, j <=
// k - 2, and rays leaving the outermost nodes. Site (i, j) has index i * k + j.
inline Diagram lattice(int k) {
  Diagram d;
  const auto s = [k](int i, int j) { return i * k + j; };
  const auto n = [k](int i, int j) { return i * (k - 1) + j; };
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) d.sites.push_back(site(i, j));
  for (int i = 0; i + 1 < k; ++i)
    for (int j = 0; j + 1 < k; ++j) d.nodes.push_back(Node{i + 0.5, j + 0.5});
  // Between (i, j) and (i + 1, j): the line x = i + 0.5 travelled along +y, site (i, j) on the
  // left; its piece for row j runs from node (i, j - 1) to node (i, j), unbounded at the lattice's
  // edges.
  for (int i = 0; i + 1 < k; ++i)
    for (int j = 0; j < k; ++j)
      d.arcs.push_back(line_arc(j == 0 ? kNone : n(i, j - 1), j == k - 1 ? kNone : n(i, j),
                                Line{i + 0.5, 0, 0, 1}, s(i, j), s(i + 1, j)));
  // Between (i, j) and (i, j + 1): the line y = j + 0.5 along +x, site (i, j + 1) on the left.
  for (int j = 0; j + 1 < k; ++j)
    for (int i = 0; i < k; ++i)
      d.arcs.push_back(line_arc(i == 0 ? kNone : n(i - 1, j), i == k - 1 ? kNone : n(i, j),
                                Line{0, j + 0.5, 1, 0}, s(i, j + 1), s(i, j)));
  return d;
}

}  // namespace covmap::check::testing
