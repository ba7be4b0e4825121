#include "report/svg_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <variant>
#include <vector>

namespace covmap::report::detail {
namespace {


struct P {
  double x = 0.0;
  double y = 0.0;
};

// How much the far box is larger than the view box on each side, as a fraction of the view's larger
// extent: enough that its edges and corners stay out of sight.
constexpr double kFarPadding = 0.5;

void include(Box& b, P p) {
  b.xmin = std::min(b.xmin, p.x);
  b.ymin = std::min(b.ymin, p.y);
  b.xmax = std::max(b.xmax, p.x);
  b.ymax = std::max(b.ymax, p.y);
}

P node_point(const Diagram& d, int node) { return {d.nodes[node].x, d.nodes[node].y}; }

int start_node(const Arc& a, bool forward) { return forward ? a.from : a.to; }
int end_node(const Arc& a, bool forward) { return forward ? a.to : a.from; }

// The foot of the perpendicular from `p` to the line: a finite point of a full line near the view.
P closest_on_line(const Line& l, P p) {
  const double t = ((p.x - l.x) * l.dx + (p.y - l.y) * l.dy) / (l.dx * l.dx + l.dy * l.dy);
  return {l.x + t * l.dx, l.y + t * l.dy};
}

P center(const Box& b) { return {(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2}; }

// Parameter interval [t0, t1] of p + t*u inside the box (p is inside, so t0 <= 0 <= t1).
std::pair<double, double> box_interval(const Box& b, P p, P u) {
  double t0 = -std::numeric_limits<double>::infinity();
  double t1 = std::numeric_limits<double>::infinity();
  const auto slab = [&](double pos, double dir, double lo, double hi) {
    if (dir == 0) return;
    const double a = (lo - pos) / dir, c = (hi - pos) / dir;
    t0 = std::max(t0, std::min(a, c));
    t1 = std::min(t1, std::max(a, c));
  };
  slab(p.x, u.x, b.xmin, b.xmax);
  slab(p.y, u.y, b.ymin, b.ymax);
  return {t0, t1};
}

// Position along the box boundary, counter-clockwise from the bottom-left corner. Points off the
// boundary (only possible through rounding) are taken to the nearest side.
double perimeter_position(const Box& b, P p) {
  const double w = b.width(), h = b.height();
  const double x = std::clamp(p.x, b.xmin, b.xmax), y = std::clamp(p.y, b.ymin, b.ymax);
  const double to_bottom = y - b.ymin, to_right = b.xmax - x, to_top = b.ymax - y, to_left = x - b.xmin;
  const double nearest = std::min({to_bottom, to_right, to_top, to_left});
  if (nearest == to_bottom) return x - b.xmin;
  if (nearest == to_right) return w + (y - b.ymin);
  if (nearest == to_top) return w + h + (b.xmax - x);
  return 2 * w + h + (b.ymax - y);
}

// One arc traversed in one direction, with its drawn end points (rays cut at the far box).
struct Step {
  const Arc* arc = nullptr;
  bool forward = true;
  P start, end;
  bool from_infinity = false;
  bool to_infinity = false;
};

Step make_step(const Diagram& d, HalfArc h, const Box& far) {
  Step s;
  s.arc = &d.arcs[h.arc];
  s.forward = h.forward;
  const int a = start_node(*s.arc, h.forward), b = end_node(*s.arc, h.forward);
  if (const auto* c = std::get_if<Circle>(&s.arc->curve)) {
    // A full circle (no nodes) is drawn from its rightmost point.
    s.start = a != kNone ? node_point(d, a) : P{c->cx + c->r, c->cy};
    s.end = b != kNone ? node_point(d, b) : s.start;
    return s;
  }
  const auto& l = std::get<Line>(s.arc->curve);
  const P u = h.forward ? P{l.dx, l.dy} : P{-l.dx, -l.dy};
  s.from_infinity = a == kNone;
  s.to_infinity = b == kNone;
  const P base = a != kNone ? node_point(d, a) : b != kNone ? node_point(d, b) : closest_on_line(l, center(far));
  const auto [t0, t1] = box_interval(far, base, u);
  s.start = a != kNone ? base : P{base.x + t0 * u.x, base.y + t0 * u.y};
  s.end = b != kNone ? node_point(d, b) : P{base.x + t1 * u.x, base.y + t1 * u.y};
  return s;
}

// Path data with one separator style: "M1 0 L-4 0 A2 2 0 0 1 -3 0 Z".
class PathText {
 public:
  void move(P p) { text_ += (text_.empty() ? "M" : " M") + point(p); }
  void line(P p) { text_ += " L" + point(p); }
  void arc(double r, bool large, bool sweep, P p) {
    text_ += " A" + svg_number(r) + " " + svg_number(r) + " 0 " + (large ? "1 " : "0 ") + (sweep ? "1 " : "0 ") + point(p);
  }
  void close() { text_ += " Z"; }
  std::string take() { return std::move(text_); }

 private:
  static std::string point(P p) { return svg_number(p.x) + " " + svg_number(p.y); }
  std::string text_;
};

// Draws the step from its start (the current point) to its end.
void draw(PathText& path, const Step& s) {
  const auto* c = std::get_if<Circle>(&s.arc->curve);
  if (!c) {
    path.line(s.end);
    return;
  }
  const bool ccw = s.forward ? s.arc->ccw : !s.arc->ccw;
  const int a = start_node(*s.arc, s.forward), b = end_node(*s.arc, s.forward);
  if (a == b) {
    // A whole circle: SVG cannot draw an arc back to its own start, so go via the antipode.
    const P opposite{2 * c->cx - s.start.x, 2 * c->cy - s.start.y};
    path.arc(c->r, false, ccw, opposite);
    path.arc(c->r, false, ccw, s.end);
    return;
  }
  constexpr double kTwoPi = 2 * std::numbers::pi;
  const double from = std::atan2(s.start.y - c->cy, s.start.x - c->cx);
  const double to = std::atan2(s.end.y - c->cy, s.end.x - c->cx);
  double ccw_span = std::fmod(to - from + 2 * kTwoPi, kTwoPi);  // in [0, 2 pi)
  const double span = ccw ? ccw_span : std::fmod(kTwoPi - ccw_span, kTwoPi);
  path.arc(c->r, span > std::numbers::pi, ccw, s.end);
}

// Walks counter-clockwise along the box boundary from `from` to `to`, through the corners between.
void walk_box(PathText& path, const Box& b, P from, P to) {
  const double w = b.width(), h = b.height(), perimeter = 2 * (w + h);
  const double t_from = perimeter_position(b, from), t_to = perimeter_position(b, to);
  const double span = std::fmod(t_to - t_from + perimeter, perimeter);
  const std::pair<double, P> corners[] = {
      {0.0, {b.xmin, b.ymin}}, {w, {b.xmax, b.ymin}}, {w + h, {b.xmax, b.ymax}}, {2 * w + h, {b.xmin, b.ymax}}};
  std::vector<std::pair<double, P>> passed;
  for (const auto& [t, corner] : corners) {
    const double along = std::fmod(t - t_from + perimeter, perimeter);
    if (along > 0 && along < span) passed.push_back({along, corner});
  }
  std::sort(passed.begin(), passed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [along, corner] : passed) path.line(corner);
  path.line(to);
}

void box_subpath(PathText& path, const Box& b) {
  path.move({b.xmin, b.ymin});
  path.line({b.xmax, b.ymin});
  path.line({b.xmax, b.ymax});
  path.line({b.xmin, b.ymax});
  path.close();
}

}  // namespace

std::string svg_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v == 0 ? 0.0 : v);  // no "-0"
  return buffer;
}

Box far_box(const Diagram& d, const Box& view) {
  Box b = view;
  for (const auto& n : d.nodes) include(b, {n.x, n.y});
  for (const auto& a : d.arcs) {
    if (const auto* c = std::get_if<Circle>(&a.curve)) {
      include(b, {c->cx - c->r, c->cy - c->r});
      include(b, {c->cx + c->r, c->cy + c->r});
    } else if (a.from == kNone && a.to == kNone) {
      include(b, closest_on_line(std::get<Line>(a.curve), center(view)));
    }
  }
  const double pad = kFarPadding * std::max({view.width(), view.height(), b.width(), b.height()});
  return {b.xmin - pad, b.ymin - pad, b.xmax + pad, b.ymax + pad};
}

std::string arc_path(const Diagram& d, int arc, const Box& far) {
  const Step s = make_step(d, {arc, true}, far);
  PathText path;
  path.move(s.start);
  draw(path, s);
  return path.take();
}

std::string face_path(const Diagram& d, const Face& face, const Box& far) {
  PathText path;
  // Pieces of boundary running from infinity to infinity, from every cycle of the face.
  std::vector<std::vector<Step>> chains;
  for (const auto cycle : face_cycles(d, face)) {
    std::vector<Step> steps;
    for (const auto& h : cycle) steps.push_back(make_step(d, h, far));
    const auto cut = std::find_if(steps.begin(), steps.end(), [](const Step& s) { return s.to_infinity; });
    if (steps.empty()) continue;
    if (cut == steps.end()) {  // a closed curve: the outer boundary of a bounded face, or a hole
      path.move(steps.front().start);
      for (const auto& s : steps) draw(path, s);
      path.close();
      continue;
    }
    // Rotate so the cycle starts right after a step into infinity, then cut after each such step.
    std::rotate(steps.begin(), cut + 1, steps.end());
    std::vector<Step> chain;
    for (auto& s : steps) {
      chain.push_back(s);
      if (s.to_infinity) chains.push_back(std::move(chain)), chain.clear();
    }
  }
  if (chains.empty()) {
    if (!face.bounded) box_subpath(path, far);  // e.g. the outside of an Apollonius circle
    return path.take();
  }

  // Join each chain to the chain whose entry comes next counter-clockwise along the far box.
  const double perimeter = 2 * (far.width() + far.height());
  std::vector<std::size_t> next(chains.size());
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const double exit = perimeter_position(far, chains[i].back().end);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < chains.size(); ++j) {
      const double along = std::fmod(perimeter_position(far, chains[j].front().start) - exit + perimeter, perimeter);
      if (along < best) best = along, next[i] = j;
    }
  }
  std::vector<bool> drawn(chains.size(), false);
  for (std::size_t first = 0; first < chains.size(); ++first) {
    if (drawn[first]) continue;
    path.move(chains[first].front().start);
    std::size_t i = first;
    while (!drawn[i]) {  // also stops on a malformed graph whose joins do not form a cycle
      drawn[i] = true;
      for (const auto& s : chains[i]) draw(path, s);
      walk_box(path, far, chains[i].back().end, chains[next[i]].front().start);
      i = next[i];
    }
    path.close();
  }
  return path.take();
}

}  // namespace covmap::report::detail
