#include "check/arc_geometry.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "core/arc_sweep.h"

namespace covmap::check::detail {
namespace {

double dist(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Liang-Barsky: the part of [s0, s1] of the line origin + s u inside box.
std::optional<std::pair<double, double>> clip_line(const ArcPath& path, const Box& box) {
  double lo = path.s0, hi = path.s1;
  const auto slab = [&](double o, double u, double mn, double mx) {
    if (u == 0.0) {
      if (o < mn || o > mx) hi = -kInfinity;  // parallel and outside: empty
      return;
    }
    double ta = (mn - o) / u, tb = (mx - o) / u;
    if (ta > tb) std::swap(ta, tb);
    lo = std::max(lo, ta);
    hi = std::min(hi, tb);
  };
  slab(path.origin.x, path.ux, box.xmin, box.xmax);
  slab(path.origin.y, path.uy, box.ymin, box.ymax);
  if (!(lo <= hi)) return std::nullopt;
  return std::make_pair(lo, hi);
}

}  // namespace

Point ArcPath::at(double s) const {
  if (circle) {
    const double t = start_angle + sense * s;
    return {centre.x + radius * std::cos(t), centre.y + radius * std::sin(t)};
  }
  return {origin.x + s * ux, origin.y + s * uy};
}

Point ArcPath::tangent(double s) const {
  if (circle) {
    const double t = start_angle + sense * s;
    return {-sense * std::sin(t), sense * std::cos(t)};
  }
  return {ux, uy};
}

ArcPath make_arc_path(const Arc& arc, const std::vector<Node>& nodes) {
  ArcPath p;
  p.from = arc.from;
  p.to = arc.to;
  if (arc.from != kNone) p.from_point = {nodes[arc.from].x, nodes[arc.from].y};
  if (arc.to != kNone) p.to_point = {nodes[arc.to].x, nodes[arc.to].y};
  if (const auto* c = std::get_if<Circle>(&arc.curve)) {
    p.circle = true;
    p.centre = {c->cx, c->cy};
    p.radius = c->r;
    p.sense = arc.ccw ? 1.0 : -1.0;
    p.s0 = 0.0;
    const CircleSweep sweep = circle_arc_sweep(arc, *c, nodes);  // the extent's one reading (core)
    p.closed = arc.from == kNone;
    p.start_angle = sweep.start_angle;
    p.s1 = sweep.sweep;
    return p;
  }
  const Line& l = std::get<Line>(arc.curve);
  const double n = std::hypot(l.dx, l.dy);
  p.origin = {l.x, l.y};
  p.ux = l.dx / n;
  p.uy = l.dy / n;
  p.s0 = arc.from == kNone ? -kInfinity : param_of(p, p.from_point);
  p.s1 = arc.to == kNone ? kInfinity : param_of(p, p.to_point);
  return p;
}

double param_of(const ArcPath& path, Point p) {
  if (path.circle) {
    const double t = std::atan2(p.y - path.centre.y, p.x - path.centre.x);
    return wrap_angle(path.sense * (t - path.start_angle));
  }
  return (p.x - path.origin.x) * path.ux + (p.y - path.origin.y) * path.uy;
}

double distance_to_curve(const ArcPath& path, Point p) {
  if (path.circle) return std::abs(dist(p, path.centre) - path.radius);
  return std::abs(path.ux * (p.y - path.origin.y) - path.uy * (p.x - path.origin.x));
}

double distance_to_arc(const ArcPath& path, Point p) {
  if (path.circle) {
    if (path.closed || param_of(path, p) <= path.s1) return distance_to_curve(path, p);
    return std::min(dist(p, path.at(path.s0)), dist(p, path.at(path.s1)));
  }
  const double s = std::clamp(param_of(path, p), path.s0, path.s1);
  return dist(p, path.at(s));
}

bool is_interior_point(const ArcPath& path, Point p, double eps) {
  const double s = param_of(path, p);
  if (path.circle) {
    if (!path.closed && s > path.s1) return false;
  } else if (s < path.s0 || s > path.s1) {
    return false;
  }
  if (path.from != kNone && dist(p, path.from_point) <= eps) return false;
  if (path.to != kNone && dist(p, path.to_point) <= eps) return false;
  return true;
}

std::vector<double> sample_parameters(const ArcPath& path, int count, const Box& window,
                                      double fallback_length) {
  double lo = path.s0, hi = path.s1;
  if (!path.bounded()) {
    const auto inside = clip_line(path, window);
    if (inside && inside->second > inside->first) {
      lo = inside->first;
      hi = inside->second;
    } else if (path.s0 > -kInfinity) {
      hi = lo + fallback_length;
    } else if (path.s1 < kInfinity) {
      lo = hi - fallback_length;
    } else {
      const double mid =
          param_of(path, {0.5 * (window.xmin + window.xmax), 0.5 * (window.ymin + window.ymax)});
      lo = mid - fallback_length;
      hi = mid + fallback_length;
    }
  }
  std::vector<double> out;
  out.reserve(count);
  for (int k = 1; k <= count; ++k) out.push_back(lo + (hi - lo) * k / (count + 1.0));
  return out;
}

Point curve_direction_at(const ArcPath& path, Point p) {
  if (!path.circle) return {path.ux, path.uy};
  const double rx = p.x - path.centre.x, ry = p.y - path.centre.y, n = std::hypot(rx, ry);
  return n > 0.0 ? Point{-ry / n, rx / n} : Point{1.0, 0.0};
}

Box bounding_box(const ArcPath& path, const Box& limit) {
  Box box;
  if (path.circle) {
    if (!path.closed) {
      box.add(path.at(path.s0));
      box.add(path.at(path.s1));
    }
    // The axis-extreme points of the circle that the arc passes.
    const Point extremes[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (const Point& e : extremes) {
      const double s = wrap_angle(path.sense * (std::atan2(e.y, e.x) - path.start_angle));
      if (path.closed || s <= path.s1)
        box.add(path.centre.x + path.radius * e.x, path.centre.y + path.radius * e.y);
    }
    return box;
  }
  if (path.bounded()) {
    box.add(path.at(path.s0));
    box.add(path.at(path.s1));
    return box;
  }
  if (const auto range = clip_line(path, limit)) {
    box.add(path.at(range->first));
    box.add(path.at(range->second));
  }
  return box;
}

std::vector<std::pair<double, double>> clip_to_box(const ArcPath& path, const Box& box) {
  std::vector<std::pair<double, double>> out;
  if (!path.circle) {
    if (const auto range = clip_line(path, box)) out.push_back(*range);
    return out;
  }
  // Split the arc where the circle crosses a box edge; each piece is wholly in or out. Crossing
  // angles come from atan2 of the crossing point (well conditioned even for huge radii).
  std::vector<double> cuts{path.s0, path.s1};
  const double r = path.radius;
  const auto add_cut = [&](double ax, double ay) {
    const double s = wrap_angle(path.sense * (std::atan2(ay, ax) - path.start_angle));
    if (s > path.s0 && s < path.s1) cuts.push_back(s);
  };
  for (const double x : {box.xmin, box.xmax}) {
    const double dx = x - path.centre.x;
    if (std::abs(dx) > r) continue;
    const double h = std::sqrt((r - std::abs(dx)) * (r + std::abs(dx)));
    add_cut(dx, h);
    add_cut(dx, -h);
  }
  for (const double y : {box.ymin, box.ymax}) {
    const double dy = y - path.centre.y;
    if (std::abs(dy) > r) continue;
    const double h = std::sqrt((r - std::abs(dy)) * (r + std::abs(dy)));
    add_cut(h, dy);
    add_cut(-h, dy);
  }
  std::sort(cuts.begin(), cuts.end());
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    if (!(b > a) || !box.contains(path.at(0.5 * (a + b)))) continue;
    if (!out.empty() && out.back().second == a) {
      out.back().second = b;
    } else {
      out.emplace_back(a, b);
    }
  }
  return out;
}

namespace {

CurveIntersection circle_circle(const ArcPath& a, const ArcPath& b, double eps) {
  CurveIntersection out;
  // Work from the smaller circle: the textbook radical-line formula loses digits when a huge circle
  // meets a small one (docs/NUMERICS.md, 'Circle–circle intersection').
  const ArcPath& p = a.radius <= b.radius ? a : b;
  const ArcPath& q = a.radius <= b.radius ? b : a;
  const double r1 = p.radius, r2 = q.radius;
  const double ex = q.centre.x - p.centre.x, ey = q.centre.y - p.centre.y;
  const double d = std::hypot(ex, ey);
  if (d <= eps && std::abs(r1 - r2) <= eps) {
    out.coincident = true;
    return out;
  }
  if (d == 0.0) return out;
  // Distance from p's centre, along the centre line, to the common chord.
  const double along = ((d - r2) * (d + r2) + r1 * r1) / (2.0 * d);
  double h2 = (r1 - along) * (r1 + along);
  if (h2 < 0.0) {
    if (std::abs(along) - r1 > eps) return out;
    h2 = 0.0;  // tangent within eps
  }
  const double h = std::sqrt(h2);
  const double ux = ex / d, uy = ey / d;
  const Point base{p.centre.x + along * ux, p.centre.y + along * uy};
  out.points.push_back({base.x - h * uy, base.y + h * ux});
  if (h > 0.0) out.points.push_back({base.x + h * uy, base.y - h * ux});
  return out;
}

CurveIntersection circle_line(const ArcPath& c, const ArcPath& l, double eps) {
  CurveIntersection out;
  const double wx = c.centre.x - l.origin.x, wy = c.centre.y - l.origin.y;
  const double t = wx * l.ux + wy * l.uy;              // foot of the centre on the line
  const double off = std::abs(l.ux * wy - l.uy * wx);  // distance of the centre from the line
  double h2 = (c.radius - off) * (c.radius + off);
  if (h2 < 0.0) {
    if (off - c.radius > eps) return out;
    h2 = 0.0;
  }
  const double h = std::sqrt(h2);
  out.points.push_back(l.at(t - h));
  if (h > 0.0) out.points.push_back(l.at(t + h));
  return out;
}

CurveIntersection line_line(const ArcPath& a, const ArcPath& b, double eps, double extent) {
  CurveIntersection out;
  const double den = a.ux * b.uy - a.uy * b.ux;  // sine of the angle between them
  const double wx = b.origin.x - a.origin.x, wy = b.origin.y - a.origin.y;
  const double off = std::abs(a.ux * wy - a.uy * wx);  // distance of b's origin from a
  if (std::abs(den) * extent <= eps) {
    // Parallel within eps over the diagram's extent: the same line or no meeting in view.
    out.coincident = off <= eps;
    return out;
  }
  const double t = (wx * b.uy - wy * b.ux) / den;
  out.points.push_back(a.at(t));
  return out;
}

}  // namespace

CurveIntersection intersect_curves(const ArcPath& a, const ArcPath& b, double eps, double extent) {
  if (a.circle && b.circle) return circle_circle(a, b, eps);
  if (a.circle) return circle_line(a, b, eps);
  if (b.circle) return circle_line(b, a, eps);
  return line_line(a, b, eps, extent);
}

bool point_in_polygon(Point p, const std::vector<Point>& polygon) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point& a = polygon[i];
    const Point& b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

}  // namespace covmap::check::detail
