#include "cleaning/tolerances.h"
#include "cleaning/rings.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace covmap::cleaning {


double twice_signed_area(const std::vector<Point>& ring) {
  // Relative to the first vertex: far-from-origin coordinates (projected metres) lose nothing.
  double area = 0.0;
  const Point o = ring.empty() ? Point{} : ring.front();
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    const double ax = ring[i].x - o.x, ay = ring[i].y - o.y;
    const double bx = ring[i + 1].x - o.x, by = ring[i + 1].y - o.y;
    area += ax * by - ay * bx;
  }
  return area;
}

Point BoundaryRing::at(double s, std::size_t* edge) const {
  const double length = perimeter();
  s = std::fmod(s, length);
  if (s < 0.0) s += length;
  // arc is increasing: the edge e with arc[e] <= s < arc[e + 1].
  auto it = std::upper_bound(arc.begin(), arc.end(), s);
  std::size_t e = it == arc.begin() ? 0 : static_cast<std::size_t>(it - arc.begin()) - 1;
  if (e >= points.size()) e = points.size() - 1;
  if (edge) *edge = e;
  const Point a = points[e], b = points[(e + 1) % points.size()];
  const double l = arc[e + 1] - arc[e];
  const double t = l > 0.0 ? std::clamp((s - arc[e]) / l, 0.0, 1.0) : 0.0;
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

namespace {

// Drops consecutive repeats (and a closing repeat of the first vertex).
std::vector<Point> without_repeats(const Ring& ring) {
  std::vector<Point> out;
  out.reserve(ring.size());
  for (const Point& p : ring) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    if (!out.empty() && out.back().x == p.x && out.back().y == p.y) continue;
    out.push_back(p);
  }
  while (out.size() > 1 && out.back().x == out.front().x && out.back().y == out.front().y) out.pop_back();
  return out;
}

void add_ring(MapRings& map, const Ring& ring, bool outer, int sensor, int cell) {
  map.input_vertices += ring.size();
  std::vector<Point> points = without_repeats(ring);
  if (points.size() < 3) return;
  const double area = twice_signed_area(points);
  if (area == 0.0) return;
  // The cell on the left: outer rings counter-clockwise, holes clockwise.
  if ((area > 0.0) != outer) std::reverse(points.begin(), points.end());
  BoundaryRing r;
  r.sensor = sensor;
  r.cell = cell;
  r.arc.resize(points.size() + 1, 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point a = points[i], b = points[(i + 1) % points.size()];
    r.arc[i + 1] = r.arc[i] + std::hypot(b.x - a.x, b.y - a.y);
  }
  r.points = std::move(points);
  map.rings.push_back(std::move(r));
}

}  // namespace

MapRings collect_rings(std::span<const CoverageCell> cells) {
  MapRings map;
  std::map<std::string, int> index;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const CoverageCell& cell = cells[c];
    if (cell.polygons.empty()) continue;
    ++map.cells;
    auto [it, fresh] = index.emplace(cell.sensor, static_cast<int>(map.sensors.size()));
    if (fresh) map.sensors.push_back(cell.sensor);
    for (const CellPolygon& polygon : cell.polygons) {
      add_ring(map, polygon.outer, true, it->second, static_cast<int>(c));
      for (const Ring& hole : polygon.holes) add_ring(map, hole, false, it->second, static_cast<int>(c));
    }
  }
  return map;
}

double estimate_bin_size(const std::vector<BoundaryRing>& rings) {
  std::vector<double> aligned;
  std::size_t edges = 0;
  for (const BoundaryRing& r : rings)
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point a = r.points[i], b = r.points[(i + 1) % r.size()];
      const double dx = std::abs(b.x - a.x), dy = std::abs(b.y - a.y);
      const double length = std::hypot(dx, dy);
      ++edges;
      if (length > 0.0 && std::min(dx, dy) <= tolerance::kAxisAlignedSlope * length) aligned.push_back(length);
    }
  if (aligned.empty() || static_cast<double>(aligned.size()) < tolerance::kRasterEdgeShare * static_cast<double>(edges))
    return 0.0;
  std::sort(aligned.begin(), aligned.end());
  // Densest window [l, kModeWindow · l] over the sorted lengths (two pointers); ties: the shorter.
  std::size_t best_begin = 0, best_end = 0, end = 0;
  for (std::size_t begin = 0; begin < aligned.size(); ++begin) {
    end = std::max(end, begin);
    while (end < aligned.size() && aligned[end] <= tolerance::kModeWindow * aligned[begin]) ++end;
    if (end - begin > best_end - best_begin) best_begin = begin, best_end = end;
  }
  // The window's median; then re-centred a few times on a window symmetric (in ratio) about the
  // estimate, which removes the upward pull of a one-sided window on jittered lengths.
  double estimate = aligned[(best_begin + best_end - 1) / 2];
  for (int round = 0; round < tolerance::kModeRecentrings; ++round) {
    const auto lo = std::lower_bound(aligned.begin(), aligned.end(), estimate / tolerance::kModeWindow);
    const auto hi = std::upper_bound(aligned.begin(), aligned.end(), estimate * tolerance::kModeWindow);
    if (hi <= lo) break;
    estimate = *(lo + (hi - lo - 1) / 2);
  }
  return estimate;
}

double median_edge_length(const std::vector<BoundaryRing>& rings) {
  std::vector<double> lengths;
  for (const BoundaryRing& r : rings)
    for (std::size_t i = 0; i < r.size(); ++i) lengths.push_back(r.arc[i + 1] - r.arc[i]);
  if (lengths.empty()) return 0.0;
  const auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), mid, lengths.end());
  return *mid;
}

}  // namespace covmap::cleaning
