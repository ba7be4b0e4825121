#include "voronoi/arc_path.h"

#include <algorithm>
#include <cmath>

namespace covmap::voronoi {
namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
}

Point ArcPathView::at(double s) const {
  if (circle) {
    const double a = start_angle + sense * s;
    return {cx + r * std::cos(a), cy + r * std::sin(a)};
  }
  return {ox + s * ux, oy + s * uy};
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
    if (arc.from == kNone) {
      p.start_angle = 0.0;
      p.s1 = kTwoPi;
      return p;
    }
    const Node& a = nodes[arc.from];
    const Node& b = nodes[arc.to];
    p.start_angle = std::atan2(a.y - c->cy, a.x - c->cx);
    if (arc.from == arc.to) {
      p.s1 = kTwoPi;
      return p;
    }
    const double end = std::atan2(b.y - c->cy, b.x - c->cx);
    double sweep = p.sense * (end - p.start_angle);
    sweep = std::fmod(sweep, kTwoPi);
    if (sweep <= 0) sweep += kTwoPi;
    p.s1 = sweep;
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
      double s = path.sense * (std::atan2(y, x) - path.start_angle);
      s = std::fmod(s, kTwoPi);
      if (s < 0) s += kTwoPi;
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

}  // namespace covmap::voronoi
