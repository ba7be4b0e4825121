#include "voronoi/arc_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/arc_sweep.h"

namespace covmap::voronoi {
Point ArcPathView::at(double s) const {
  if (circle) {
    const double a = start_angle + sense * s;
    return {cx + r * std::cos(a), cy + r * std::sin(a)};
  }
  return {ox + s * ux, oy + s * uy};
}

double ArcPathView::param_of(Point q) const {
  if (circle) return wrap_angle(sense * (std::atan2(q.y - cy, q.x - cx) - start_angle));
  return (q.x - ox) * ux + (q.y - oy) * uy;
}

Point ArcPathView::tangent(double s) const {
  if (circle) {
    const double a = start_angle + sense * s;
    return {-sense * std::sin(a), sense * std::cos(a)};
  }
  return {ux, uy};
}

ArcPathView arc_path(const Arc& arc, const std::vector<Node>& nodes) {
  ArcPathView p;
  if (const Circle* c = std::get_if<Circle>(&arc.curve)) {
    p.circle = true;
    p.cx = c->cx;
    p.cy = c->cy;
    p.r = c->r;
    p.sense = arc.ccw ? 1.0 : -1.0;
    const CircleSweep sweep = circle_arc_sweep(arc, *c, nodes);  // the extent's one reading (core)
    p.start_angle = sweep.start_angle;
    p.s1 = sweep.sweep;
    return p;
  }
  const Line& l = std::get<Line>(arc.curve);
  const double len = std::hypot(l.dx, l.dy);
  p.ox = l.x;
  p.oy = l.y;
  p.ux = l.dx / len;
  p.uy = l.dy / len;
  auto param = [&](const Node& n) { return (n.x - l.x) * p.ux + (n.y - l.y) * p.uy; };
  p.s0 = arc.from == kNone ? -kPathInfinity : param(nodes[arc.from]);
  p.s1 = arc.to == kNone ? kPathInfinity : param(nodes[arc.to]);
  return p;
}

std::vector<double> path_segment_crossings(const ArcPathView& path, Point a, Point b) {
  std::vector<double> out;
  const double dx = b.x - a.x, dy = b.y - a.y;
  if (path.circle) {
    // |a + t d - c|² = r², t ∈ [0, 1]
    const double fx = a.x - path.cx, fy = a.y - path.cy;
    const double qa = dx * dx + dy * dy, qb = 2 * (fx * dx + fy * dy),
                 qc = fx * fx + fy * fy - path.r * path.r;
    const double disc = qb * qb - 4 * qa * qc;
    if (qa == 0 || disc < 0) return out;
    const double sq = std::sqrt(disc);
    const double q = -0.5 * (qb + (qb >= 0 ? sq : -sq));
    for (double t : {q / qa, q != 0 ? qc / q : -qb / (2 * qa)}) {
      if (t < 0 || t > 1) continue;
      const double x = a.x + t * dx - path.cx, y = a.y + t * dy - path.cy;
      const double s = path.param_of({x + path.cx, y + path.cy});
      if (s >= path.s0 && s <= path.s1) out.push_back(s);
    }
  } else {
    // o + s u = a + t d
    const double den = path.ux * dy - path.uy * dx;
    if (den == 0) return out;
    const double wx = a.x - path.ox, wy = a.y - path.oy;
    const double s = (wx * dy - wy * dx) / den;
    const double t = (wx * path.uy - wy * path.ux) / den;
    if (t >= 0 && t <= 1 && s >= path.s0 && s <= path.s1) out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double pseudo_angle(double x, double y) {
  const double s = std::abs(x) + std::abs(y);
  if (s == 0) return 0.0;
  const double t = y / s;  // in [-1, 1]
  if (x >= 0) return t >= 0 ? t : kPseudoTurn + t;
  return 0.5 * kPseudoTurn - t;
}

namespace {

// Bounds only preselect arcs for exact tests (face tracing, comparison); this many ulps of the
// coordinates cover the rounding of the ends and extreme points.
constexpr double kBoundsPadUlps = 4.0;

void grow(Box& b, double x, double y) { b.add(x, y); }

}  // namespace

Box arc_bounds(const Arc& arc, const Node& from, const Node& to) {
  Box b;
  if (const Circle* c = std::get_if<Circle>(&arc.curve)) {
    if (arc.from == kNone || arc.from == arc.to) {
      b = {c->cx - c->r, c->cy - c->r, c->cx + c->r, c->cy + c->r};
    } else {
      const Node& a = from;
      const Node& e = to;
      grow(b, a.x, a.y);
      grow(b, e.x, e.y);
      // Counter-clockwise from the start direction to the end direction (reversed for clockwise
      // arcs: then the sweep runs from the end to the start).
      const double pa = pseudo_angle(a.x - c->cx, a.y - c->cy), pe = pseudo_angle(e.x - c->cx, e.y - c->cy);
      const double lo = arc.ccw ? pa : pe, hi = arc.ccw ? pe : pa;
      double span = hi - lo;
      if (span <= 0) span += kPseudoTurn;
      const double extreme[4][2] = {{c->cx + c->r, c->cy}, {c->cx, c->cy + c->r}, {c->cx - c->r, c->cy}, {c->cx, c->cy - c->r}};
      for (int k = 0; k < 4; ++k) {
        double at = k - lo;  // pseudo-angles of the axis directions are 0, 1, 2, 3
        if (at < 0) at += kPseudoTurn;
        if (at <= span) grow(b, extreme[k][0], extreme[k][1]);
      }
    }
  } else {
    if (arc.from == kNone || arc.to == kNone) return {-INFINITY, -INFINITY, INFINITY, INFINITY};
    grow(b, from.x, from.y);
    grow(b, to.x, to.y);
  }
  const double pad = kBoundsPadUlps * std::numeric_limits<double>::epsilon() *
                     std::max({std::abs(b.xmin), std::abs(b.ymin), std::abs(b.xmax), std::abs(b.ymax)});
  return {b.xmin - pad, b.ymin - pad, b.xmax + pad, b.ymax + pad};
}

Box arc_bounds(const Arc& arc, const std::vector<Node>& nodes) {
  const Node none{};
  return arc_bounds(arc, arc.from == kNone ? none : nodes[arc.from], arc.to == kNone ? none : nodes[arc.to]);
}


}  // namespace covmap::voronoi
