#include "report/audit_html_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "report/audit_geometry.h"
#include "report/audit_html_text.h"
#include "report/svg.h"

namespace covmap::report::detail {
namespace {


// Things this many view widths (or heights) outside the map are not drawn: nobody pans there, and
// their coordinates would only lengthen the file.
constexpr double kFarAway = 100.0;

// Sizes of the marks, in screen pixels at the nominal width.
constexpr double kDotRadiusPx = 4.0;
constexpr double kReportedRadiusPx = 3.0;
constexpr double kArrowHeadPx = 9.0;

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

struct Frame {
  double xmin = 0.0, ymax = 0.0;
  double scale = 1.0;  // grid units per map unit
  std::int64_t width = 1, height = 1;

  GridPoint at(Point p) const { return {std::llround((p.x - xmin) * scale), std::llround((ymax - p.y) * scale)}; }
  bool drawable(Point p) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    const double gx = (p.x - xmin) * scale, gy = (ymax - p.y) * scale;
    return std::abs(gx) <= kFarAway * static_cast<double>(width) && std::abs(gy) <= kFarAway * static_cast<double>(height);
  }
};

Frame make_frame(const AuditReportContext& c) {
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
  Frame f;
  f.xmin = xmin;
  f.ymax = ymax;
  f.scale = c.render.html_width_px / c.render.html_grid_px / (xmax - xmin);
  f.width = std::max<std::int64_t>(1, std::llround((xmax - xmin) * f.scale));
  f.height = std::max<std::int64_t>(1, std::llround((ymax - ymin) * f.scale));
  return f;
}

// Appends one ring or polyline, rounded and simplified, to the path data `d`.
void append_path(std::string& d, const Frame& f, std::span<const Point> points, double tolerance, bool closed) {
  std::vector<GridPoint> grid;
  grid.reserve(points.size());
  for (const Point& p : points) {
    if (!f.drawable(p)) return;  // a broken or far-away piece is left out whole
    grid.push_back(f.at(p));
  }
  const std::vector<GridPoint> kept = simplify(grid, tolerance, closed);
  if (!kept.empty()) d += grid_path(kept, closed);
}

std::string number(std::int64_t v) { return std::to_string(v); }

// The path data of every arc of `d` that is (frame) or is not (!frame) a frame arc.
std::string arcs_path(const Diagram& d, const Frame& f, const AuditRenderOptions& o, bool frame) {
  const ArcSampling sampling = arc_sampling(o, diagram_extent(d), false);
  const double tolerance = o.html_simplify_px / o.html_grid_px;
  std::string path;
  for (std::size_t i = 0; i < d.arcs.size(); ++i) {
    if (d.arcs[i].frame != frame) continue;
    const auto points = sample_half_arc(d, {static_cast<int>(i), true}, sampling);
    if (!points.empty()) append_path(path, f, points, tolerance, false);
  }
  return path;
}

std::string sensor_title(const audit::SensorAudit& s) {
  std::string t = s.id + " \xE2\x80\x94 " + std::string(verdict_words(s.verdict));
  if (s.in_map) {
    t += "\nweight " + human_number(s.weight, 4);
    if (s.tx_power_dbm) t += ", power " + human_number(*s.tx_power_dbm, 4) + " dBm";
    if (s.uncertainty_available) t += "\nposition \xC2\xB1 " + human_number(s.sigma_position_m) + " m (1\xCF\x83)";
  }
  if (s.reported && s.in_map) {
    t += "\nmoved " + human_number(s.position_error_m) + " m from the reported position";
    if (s.power_error_db) t += "\npower error " + human_number(*s.power_error_db) + " dB";
  }
  if (s.chi2) t += "\n\xCF\x87\xC2\xB2 = " + human_number(*s.chi2);
  if (!s.reason.empty()) t += "\n" + s.reason;
  return html_escape(t);
}

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

std::string grid_path(std::span<const GridPoint> points, bool closed) {
  if (points.empty()) return {};
  // Appended piecewise rather than with "M" + ...: GCC 12 false -Wrestrict (PR 105651).
  std::string d(1, 'M');
  d += number(points[0].x);
  d += ' ';
  d += number(points[0].y);
  if (points.size() > 1) d += "l";
  bool first = true;
  const auto put = [&](std::int64_t v) {
    // After the command letter, and before a minus sign, no separator is needed.
    if (!first && v >= 0) d += ' ';
    d += number(v);
    first = false;
  };
  for (std::size_t i = 1; i < points.size(); ++i) {
    put(points[i].x - points[i - 1].x);
    put(points[i].y - points[i - 1].y);
  }
  if (closed) d += "z";
  return d;
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

std::string verdict_class(audit::SensorVerdict verdict) {
  std::string c = "v-" + std::string(audit::to_string(verdict));
  std::replace(c.begin(), c.end(), '_', '-');
  return c;
}

void write_audit_map_svg(const AuditReportContext& c, std::ostream& out) {
  const AuditRenderOptions& o = c.render;
  const Frame f = make_frame(c);
  const double tolerance = o.html_simplify_px / o.html_grid_px;
  const auto units = [&](double px) { return number(std::llround(px / o.html_grid_px)); };
  const auto xy = [&](const char* xname, const char* yname, Point p) {
    const GridPoint g = f.at(p);
    return std::string(" ") + xname + "=\"" + number(g.x) + "\" " + yname + "=\"" + number(g.y) + "\"";
  };
  const audit::AuditResult& r = c.result;

  std::unordered_map<std::string, std::size_t> sensor_index;
  for (std::size_t i = 0; i < r.sensors.size(); ++i) sensor_index.emplace(r.sensors[i].id, i);

  out << "<svg id=\"map\" viewBox=\"0 0 " << f.width << ' ' << f.height << "\" width=\"" << human_number(o.html_width_px, 10)
      << "\" height=\"" << human_number(static_cast<double>(f.height) * o.html_grid_px, 10)
      << "\" preserveAspectRatio=\"xMidYMid meet\" role=\"img\" aria-label=\"coverage map\">\n";
  out << "<defs>\n";
  // One arrow head per verdict.
  for (const audit::SensorVerdict verdict : audit::kAllSensorVerdicts) {
    out << "<marker id=\"arrow-" << verdict_class(verdict) << "\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerUnits=\"userSpaceOnUse\" markerWidth=\""
        << units(kArrowHeadPx) << "\" markerHeight=\"" << units(kArrowHeadPx)
        << "\" orient=\"auto\"><path d=\"M0 0L10 5L0 10z\" fill=\"" << verdict_colour(verdict) << "\"/></marker>\n";
  }
  out << "</defs>\n";

  out << "<g id=\"layer-cells\" class=\"cells\" fill-rule=\"evenodd\">\n";
  for (const auto& cell : c.map.cells) {
    std::string d;
    for (const auto& polygon : cell.polygons) {
      append_path(d, f, polygon.outer, tolerance, true);
      for (const auto& hole : polygon.holes) append_path(d, f, hole, tolerance, true);
    }
    if (d.empty()) continue;
    const auto it = sensor_index.find(cell.sensor);
    out << "<path fill=\"" << (it != sensor_index.end() ? site_colour(it->second) : std::string("#dddddd")) << "\" d=\""
        << d << "\"><title>" << html_escape(cell.sensor) << "</title></path>\n";
  }
  out << "</g>\n";

  if (r.reported_diagram) {
    out << "<g id=\"layer-reported-diagram\" class=\"hidden\"><path class=\"reported-diagram\" d=\""
        << arcs_path(*r.reported_diagram, f, o, false) << "\"/></g>\n";
  }
  out << "<g id=\"layer-diagram\"><path class=\"frame\" d=\"" << arcs_path(r.refined_diagram, f, o, true)
      << "\"/><path class=\"boundaries\" d=\"" << arcs_path(r.refined_diagram, f, o, false) << "\"/></g>\n";

  out << "<g id=\"layer-shifts\">\n";
  for (const auto& s : r.sensors) {
    if (!s.in_map || !s.reported || !f.drawable(s.position) || !f.drawable(s.reported->position)) continue;
    out << "<line class=\"shift " << verdict_class(s.verdict) << "\"" << xy("x1", "y1", s.reported->position)
        << xy("x2", "y2", s.position) << " stroke=\"" << verdict_colour(s.verdict) << "\" marker-end=\"url(#arrow-"
        << verdict_class(s.verdict) << ")\"><title>" << sensor_title(s) << "</title></line>\n";
  }
  out << "</g>\n<g id=\"layer-sensors\">\n";
  for (const auto& s : r.sensors) {
    if (!s.reported || !f.drawable(s.reported->position)) continue;
    out << "<circle class=\"reported " << verdict_class(s.verdict) << "\"" << xy("cx", "cy", s.reported->position)
        << " r=\"" << units(kReportedRadiusPx) << "\" stroke=\"" << verdict_colour(s.verdict) << "\"><title>"
        << html_escape(s.id) << " (reported position)</title></circle>\n";
  }
  for (const auto& s : r.sensors) {
    if (!s.in_map || !f.drawable(s.position)) continue;
    out << "<circle class=\"sensor " << verdict_class(s.verdict) << "\"" << xy("cx", "cy", s.position) << " r=\""
        << units(kDotRadiusPx) << "\" fill=\"" << verdict_colour(s.verdict) << "\"><title>" << sensor_title(s)
        << "</title></circle>\n";
  }
  out << "</g>\n</svg>\n";
}

}  // namespace covmap::report::detail
