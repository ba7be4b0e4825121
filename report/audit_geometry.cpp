#include "report/audit_geometry.h"

#include "core/box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "voronoi/arc_path.h"

namespace covmap::report::detail {
namespace {


constexpr double kPi = 3.14159265358979323846;

bool same(Point a, Point b) { return a.x == b.x && a.y == b.y; }


// Equal steps over [0, sweep]: enough for the angle bound and for the sagitta bound.
int circle_segments(double sweep, double r, const ArcSampling& s) {
  double step = s.max_step_radians;
  // The sagitta of a chord spanning angle t is r (1 - cos(t / 2)); it stays below max_deviation
  // for t <= 2 acos(1 - max_deviation / r). A circle smaller than the deviation needs no more.
  if (s.max_deviation < r) step = std::min(step, 2.0 * std::acos(1.0 - s.max_deviation / r));
  return std::max(1, static_cast<int>(std::ceil(sweep / step)));
}

}  // namespace

double diagram_extent(const Diagram& d) {
  Box b;
  if (!d.clip.empty()) {
    for (const auto& p : d.clip) b.add_finite(p.x, p.y);
  } else {
    for (const auto& n : d.nodes) b.add_finite(n.x, n.y);
    for (const auto& s : d.sites) b.add_finite(s.x, s.y);
  }
  const double diagonal = b.diagonal();
  return diagonal > 0 ? diagonal : 1.0;
}

ArcSampling arc_sampling(const AuditRenderOptions& o, double extent, bool geographic) {
  ArcSampling s;
  s.max_step_radians = o.arc_step_degrees * kPi / 180.0;
  s.max_deviation = o.arc_deviation * extent;
  s.max_line_step = geographic ? o.geographic_line_step * extent : std::numeric_limits<double>::infinity();
  return s;
}

std::vector<Point> sample_half_arc(const Diagram& d, HalfArc h, const ArcSampling& s) {
  const Arc& arc = d.arcs[h.arc];
  const voronoi::ArcPathView path = voronoi::arc_path(arc, d.nodes);
  if (!std::isfinite(path.s0) || !std::isfinite(path.s1)) return {};
  int n = 1;
  if (path.circle) {
    n = circle_segments(path.s1 - path.s0, path.r, s);
  } else if (std::isfinite(s.max_line_step)) {
    n = std::max(1, static_cast<int>(std::ceil((path.s1 - path.s0) / s.max_line_step)));
  }
  std::vector<Point> points;
  points.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) points.push_back(path.at(path.s0 + (path.s1 - path.s0) * i / n));
  // The nodes are the shared truth between consecutive arcs; cos/sin would be off by an ulp or so.
  if (arc.from != kNone) points.front() = {d.nodes[arc.from].x, d.nodes[arc.from].y};
  if (arc.to != kNone) points.back() = {d.nodes[arc.to].x, d.nodes[arc.to].y};
  if (arc.from == kNone && path.circle) points.back() = points.front();  // a full circle closes
  if (!h.forward) std::reverse(points.begin(), points.end());
  return points;
}

Ring sample_cycle(const Diagram& d, std::span<const HalfArc> cycle, const ArcSampling& s) {
  Ring ring;
  for (const auto& h : cycle) {
    const std::vector<Point> points = sample_half_arc(d, h, s);
    if (points.empty()) return {};
    // A node that failed to compute would make the whole polygon meaningless (and JSON invalid).
    if (!std::all_of(points.begin(), points.end(), [](Point p) { return std::isfinite(p.x) && std::isfinite(p.y); })) {
      return {};
    }
    // Each arc's last point is the next arc's first (the cycle's first point closes the ring).
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      if (ring.empty() || !same(ring.back(), points[i])) ring.push_back(points[i]);
    }
  }
  while (ring.size() > 1 && same(ring.back(), ring.front())) ring.pop_back();
  std::size_t distinct = 0;
  for (std::size_t i = 0; i < ring.size() && distinct < 3; ++i) {
    if (std::none_of(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(i), [&](Point q) { return same(q, ring[i]); })) {
      ++distinct;
    }
  }
  if (distinct < 3) return {};
  return ring;
}

double signed_area(const Ring& ring) {
  if (ring.size() < 3) return 0.0;
  // Relative to the first vertex: products of small differences lose less to cancellation.
  const Point o = ring.front();
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    twice += (ring[i].x - o.x) * (ring[i + 1].y - o.y) - (ring[i + 1].x - o.x) * (ring[i].y - o.y);
  }
  return twice / 2.0;
}

DiagramRegions diagram_regions(const Diagram& d, const ArcSampling& s) {
  DiagramRegions out;
  std::map<int, SiteRegion> by_site;
  for (const auto& face : d.faces) {
    if (!face.bounded) {
      ++out.unbounded_faces;
      continue;
    }
    const FaceCycles cycles = face_cycles(d, face);
    if (cycles.empty()) {
      ++out.degenerate_faces;
      continue;
    }
    io::MapPolygon polygon;
    polygon.outer = sample_cycle(d, cycles.front(), s);
    if (polygon.outer.empty()) {
      ++out.degenerate_faces;
      continue;
    }
    if (signed_area(polygon.outer) < 0) std::reverse(polygon.outer.begin(), polygon.outer.end());
    double area = signed_area(polygon.outer);
    for (std::size_t b = 1; b < cycles.size(); ++b) {
      Ring hole = sample_cycle(d, cycles[b], s);
      if (hole.empty()) continue;  // a hole too small to have three distinct points has no area
      if (signed_area(hole) > 0) std::reverse(hole.begin(), hole.end());
      area += signed_area(hole);
      polygon.holes.push_back(std::move(hole));
    }
    SiteRegion& region = by_site[face.site];
    region.site = face.site;
    region.orphan_faces += face.orphan ? 1 : 0;
    region.area += area;
    region.polygons.push_back(std::move(polygon));
  }
  for (auto& [site, region] : by_site) out.regions.push_back(std::move(region));
  return out;
}

io::LonLat to_lonlat(const io::MapFrame& projection, Point p) { return projection.inverse(p); }

io::LonLat to_lonlat_continuous(const io::MapFrame& projection, Point p) {
  io::LonLat g = projection.inverse(p);
  g.lon = projection.reference().lon + std::remainder(g.lon - projection.reference().lon, 360.0);
  return g;
}

}  // namespace covmap::report::detail
