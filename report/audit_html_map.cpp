#include "report/audit_html_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "report/audit_geometry.h"

namespace covmap::report::detail {
namespace {


// Things this many view widths (or heights) outside the map are not drawn: nobody pans there, and
// their coordinates would only lengthen the file.
constexpr double kFarAway = 100.0;

double segment_distance(const GridPoint& p, const GridPoint& a, const GridPoint& b) {
  const double dx = static_cast<double>(b.x - a.x), dy = static_cast<double>(b.y - a.y);
  const double px = static_cast<double>(p.x - a.x), py = static_cast<double>(p.y - a.y);
  const double length2 = dx * dx + dy * dy;
  if (length2 == 0) return std::hypot(px, py);
  const double t = std::clamp((px * dx + py * dy) / length2, 0.0, 1.0);
  return std::hypot(px - t * dx, py - t * dy);
}

// Marks in `keep` the points of pts[first..last] that Douglas-Peucker keeps (first and last are
// kept by the caller). An explicit stack: rings of 10^5 vertices would overflow a recursion.
void douglas_peucker(const std::vector<GridPoint>& pts, std::size_t first, std::size_t last, double tolerance,
                     std::vector<char>& keep) {
  std::vector<std::pair<std::size_t, std::size_t>> stack{{first, last}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = -1.0;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = segment_distance(pts[i], pts[a], pts[b]);
      if (d > worst) {
        worst = d;
        at = i;
      }
    }
    if (at == a || worst <= tolerance) continue;
    keep[at] = 1;
    stack.push_back({a, at});
    stack.push_back({at, b});
  }
}


// Appends one ring or polyline, rounded and simplified, to `out`.
void append_piece(std::vector<std::vector<std::int64_t>>& out, const GridFrame& f, std::span<const Point> points,
                  double tolerance, bool closed) {
  std::vector<GridPoint> grid;
  grid.reserve(points.size());
  for (const Point& p : points) {
    if (!f.drawable(p)) return;  // a broken or far-away piece is left out whole
    grid.push_back(f.at(p));
  }
  const std::vector<GridPoint> kept = simplify(grid, tolerance, closed);
  if (!kept.empty()) out.push_back(delta_encode(kept));
}

double simplify_tolerance(const AuditRenderOptions& o) { return o.html_simplify_px / o.html_grid_px; }

}  // namespace

std::vector<GridPoint> simplify(std::span<const GridPoint> points, double tolerance, bool closed) {
  std::vector<GridPoint> q;
  q.reserve(points.size() + 1);
  for (const GridPoint& p : points) {
    if (q.empty() || !(q.back() == p)) q.push_back(p);
  }
  if (closed) {
    while (q.size() > 1 && q.back() == q.front()) q.pop_back();
    if (q.size() < 3) return {};
    // Split the ring at its first point and the point farthest from it; both are kept.
    std::size_t far = 0;
    double far_distance = -1.0;
    for (std::size_t i = 1; i < q.size(); ++i) {
      const double d = std::hypot(static_cast<double>(q[i].x - q[0].x), static_cast<double>(q[i].y - q[0].y));
      if (d > far_distance) {
        far_distance = d;
        far = i;
      }
    }
    const std::size_t n = q.size();
    q.push_back(q.front());
    std::vector<char> keep(q.size(), 0);
    keep[0] = keep[far] = keep[n] = 1;
    douglas_peucker(q, 0, far, tolerance, keep);
    douglas_peucker(q, far, n, tolerance, keep);
    std::vector<GridPoint> out;
    for (std::size_t i = 0; i < n; ++i) {
      if (keep[i]) out.push_back(q[i]);
    }
    if (out.size() < 3) return {};
    return out;
  }
  if (q.size() < 2) return {};
  std::vector<char> keep(q.size(), 0);
  keep.front() = keep.back() = 1;
  douglas_peucker(q, 0, q.size() - 1, tolerance, keep);
  std::vector<GridPoint> out;
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (keep[i]) out.push_back(q[i]);
  }
  return out;
}

std::vector<std::int64_t> delta_encode(std::span<const GridPoint> points) {
  std::vector<std::int64_t> out;
  out.reserve(2 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    out.push_back(i ? points[i].x - points[i - 1].x : points[i].x);
    out.push_back(i ? points[i].y - points[i - 1].y : points[i].y);
  }
  return out;
}

GridPoint GridFrame::at(Point p) const {
  return {std::llround((p.x - xmin) * scale), std::llround((ymax - p.y) * scale)};
}

Point GridFrame::map_point(double gx, double gy) const { return {xmin + gx / scale, ymax - gy / scale}; }

bool GridFrame::drawable(Point p) const {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  const double gx = (p.x - xmin) * scale, gy = (ymax - p.y) * scale;
  return std::abs(gx) <= kFarAway * static_cast<double>(width) && std::abs(gy) <= kFarAway * static_cast<double>(height);
}

GridFrame grid_frame(const AuditReportContext& c) {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin;
  double xmax = -xmin, ymax = -xmin;
  const auto add = [&](Point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    xmin = std::min(xmin, p.x);
    ymin = std::min(ymin, p.y);
    xmax = std::max(xmax, p.x);
    ymax = std::max(ymax, p.y);
  };
  for (const auto& cell : c.map.cells)
    for (const auto& polygon : cell.polygons)
      for (const Point& p : polygon.outer) add(p);
  if (!(xmin <= xmax)) {  // no map to frame: the diagram's clip, else the sensors
    for (const Point& p : c.result.refined_diagram.clip) add(p);
    for (const auto& s : c.result.sensors) add(s.position);
  }
  if (!(xmin <= xmax)) xmin = ymin = 0.0, xmax = ymax = 1.0;
  // A degenerate box still needs two dimensions to be drawn.
  double side = std::max(xmax - xmin, ymax - ymin);
  if (side == 0) side = std::max(1.0, std::max(std::abs(xmin), std::abs(ymin)));
  const double grow_x = (side - (xmax - xmin)) * (xmax - xmin == 0 ? 0.5 : 0.0);
  const double grow_y = (side - (ymax - ymin)) * (ymax - ymin == 0 ? 0.5 : 0.0);
  const double pad = c.render.html_margin * side;
  xmin -= pad + grow_x;
  xmax += pad + grow_x;
  ymin -= pad + grow_y;
  ymax += pad + grow_y;
  GridFrame f;
  f.xmin = xmin;
  f.ymax = ymax;
  f.scale = c.render.html_width_px / c.render.html_grid_px / (xmax - xmin);
  f.width = std::max<std::int64_t>(1, std::llround((xmax - xmin) * f.scale));
  f.height = std::max<std::int64_t>(1, std::llround((ymax - ymin) * f.scale));
  return f;
}

std::vector<std::vector<std::int64_t>> cell_rings(const GridFrame& f, const AuditRenderOptions& o, const io::MapCell& cell) {
  std::vector<std::vector<std::int64_t>> rings;
  for (const auto& polygon : cell.polygons) {
    append_piece(rings, f, polygon.outer, simplify_tolerance(o), true);
    for (const auto& hole : polygon.holes) append_piece(rings, f, hole, simplify_tolerance(o), true);
  }
  return rings;
}

std::vector<std::vector<std::int64_t>> diagram_arcs(const GridFrame& f, const AuditRenderOptions& o, const Diagram& d,
                                                    bool frame) {
  const ArcSampling sampling = arc_sampling(o, diagram_extent(d), false);
  std::vector<std::vector<std::int64_t>> arcs;
  for (std::size_t i = 0; i < d.arcs.size(); ++i) {
    if (d.arcs[i].frame != frame) continue;
    const auto points = sample_half_arc(d, {static_cast<int>(i), true}, sampling);
    if (!points.empty()) append_piece(arcs, f, points, simplify_tolerance(o), false);
  }
  return arcs;
}

std::string verdict_colour(audit::SensorVerdict verdict) {
  switch (verdict) {
    case audit::SensorVerdict::kConsistent: return "#1a9850";
    case audit::SensorVerdict::kInconsistent: return "#d73027";
    case audit::SensorVerdict::kNotInMap: return "#e08000";
    case audit::SensorVerdict::kUnreported: return "#2b6cb0";
    case audit::SensorVerdict::kUndetermined: return "#7a7a7a";
    case audit::SensorVerdict::kModelMisfit: return "#8e44ad";
  }
  throw std::logic_error("verdict_colour: a verdict outside the enumeration");
}

std::size_t verdict_index(audit::SensorVerdict verdict) {
  for (std::size_t v = 0; v < std::size(audit::kAllSensorVerdicts); ++v)
    if (audit::kAllSensorVerdicts[v] == verdict) return v;
  throw std::logic_error("verdict_index: a verdict outside the enumeration");
}

std::string verdict_class(audit::SensorVerdict verdict) {
  std::string c = "v-" + std::string(audit::to_string(verdict));
  std::replace(c.begin(), c.end(), '_', '-');
  return c;
}

}  // namespace covmap::report::detail
