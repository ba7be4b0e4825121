#include "checks.h"

#include "core/orientation.h"
#include "io/polygon_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <variant>

namespace covmap::fuzz {
namespace {

bool finite(double v) { return std::isfinite(v); }
bool finite(Point p) { return finite(p.x) && finite(p.y); }
bool same(Point a, Point b) { return a.x == b.x && a.y == b.y; }

// The ring multiplied by a power of two that brings its largest coordinate magnitude into [0.5, 1),
// or nullopt when its smallest non-zero magnitude would then fall below 2^-kMaxSpread. Scaling by a
// power of two is exact (no rounding) and keeps every orientation; afterwards the products in an
// orientation test lie between about 2^-(2 kMaxSpread + 106) and 4, far from overflow and from
// the subnormal range, which is the range core/orientation.h promises exact answers in.
constexpr int kMaxSpread = 400;

std::optional<std::vector<Point>> tame_scale(std::span<const Point> ring) {
  int top = std::numeric_limits<int>::min(), bottom = std::numeric_limits<int>::max();
  for (const Point& p : ring) {
    for (const double c : {p.x, p.y}) {
      if (c == 0) continue;
      int exponent = 0;
      std::frexp(c, &exponent);  // |c| in [2^(exponent-1), 2^exponent)
      top = std::max(top, exponent);
      bottom = std::min(bottom, exponent);
    }
  }
  if (top == std::numeric_limits<int>::min()) return std::vector<Point>(ring.begin(), ring.end());  // all zero
  if (top - bottom > kMaxSpread) return std::nullopt;
  std::vector<Point> out;
  out.reserve(ring.size());
  for (const Point& p : ring) out.push_back({std::ldexp(p.x, -top), std::ldexp(p.y, -top)});
  return out;
}

// The turn at the lowest (then leftmost) vertex: the orientation of a ring that does not double
// back there.
int turn_at_lowest(std::span<const Point> ring) {
  std::size_t low = 0;
  for (std::size_t i = 1; i < ring.size(); ++i) {
    if (ring[i].y < ring[low].y || (ring[i].y == ring[low].y && ring[i].x < ring[low].x)) low = i;
  }
  const std::size_t n = ring.size();
  return orientation(ring[(low + n - 1) % n], ring[low], ring[(low + 1) % n]);
}

// An index into `count` things, or kNone when allowed.
bool index_ok(int i, std::size_t count, bool allow_none) {
  if (i == kNone) return allow_none;
  return i >= 0 && static_cast<std::size_t>(i) < count;
}

}  // namespace

void require(bool holds, std::string_view promise) { require(holds, "", promise); }

void require(bool holds, std::string_view what, std::string_view promise) {
  if (holds) return;
  std::fprintf(stderr, "fuzz: broken promise: %.*s%s%.*s\n", static_cast<int>(what.size()), what.data(),
               what.empty() ? "" : ": ", static_cast<int>(promise.size()), promise.data());
  std::abort();
}

void check_sites(const std::vector<Site>& sites) {
  require(!sites.empty(), "sites: at least one site");
  std::set<std::string> ids;
  std::set<std::pair<double, double>> positions;  // ordered by <, so -0 and 0 are one position
  for (const Site& s : sites) {
    require(!s.id.empty(), "sites: ids are not empty");
    require(ids.insert(s.id).second, "sites: ids are unique");
    require(finite(s.x) && finite(s.y), "sites: positions are finite");
    require(finite(s.weight) && s.weight > 0, "sites: weights are finite and > 0");
    require(positions.insert({s.x, s.y}).second, "sites: no two sites at the same position");
  }
}

void check_ring(std::span<const Point> ring, std::string_view what) {
  require(ring.size() >= 3, what, "at least 3 vertices");
  for (std::size_t i = 0; i < ring.size(); ++i) {
    require(finite(ring[i]), what, "finite coordinates");
    require(!same(ring[i], ring[(i + 1) % ring.size()]), what, "no two consecutive vertices equal (closing one included)");
  }
}

void check_clip_polygon(std::span<const Point> ring, std::string_view what) {
  check_ring(ring, what);
  if (const auto tame = tame_scale(ring)) {
    require(!io::polygon_defect(*tame), what, "simple with non-zero area (judged at a tame scale)");
    require(turn_at_lowest(*tame) == 1, what, "counter-clockwise (judged at a tame scale)");
  }
}

void check_diagram(const Diagram& d, io::ArcLabels labels) {
  const bool labelled = labels == io::ArcLabels::kRequired;
  if (labelled) {
    check_sites(d.sites);
  } else {
    require(d.sites.empty() && d.faces.empty(), "arcgraph (labels ignored): no sites and no faces");
  }
  for (const Node& n : d.nodes) require(finite(n.x) && finite(n.y), "arcgraph: nodes are finite");
  for (const Arc& a : d.arcs) {
    require(index_ok(a.from, d.nodes.size(), true) && index_ok(a.to, d.nodes.size(), true), "arcgraph: arc ends in range");
    if (const auto* c = std::get_if<Circle>(&a.curve)) {
      require(finite(c->cx) && finite(c->cy) && finite(c->r) && c->r > 0, "arcgraph: circles finite with radius > 0");
      require((a.from == kNone) == (a.to == kNone), "arcgraph: circle arcs have both ends or neither");
    } else {
      const auto& l = std::get<Line>(a.curve);
      require(finite(l.x) && finite(l.y) && finite(l.dx) && finite(l.dy), "arcgraph: lines finite");
      require(l.dx != 0 || l.dy != 0, "arcgraph: line direction not zero");
    }
    if (!labelled) {
      require(a.left_site == kNone && a.right_site == kNone, "arcgraph (labels ignored): arcs carry no sites");
      continue;
    }
    require(index_ok(a.left_site, d.sites.size(), true) && index_ok(a.right_site, d.sites.size(), true),
            "arcgraph: arc sites in range");
    const int named = (a.left_site != kNone) + (a.right_site != kNone);
    if (a.frame) {
      require(named == 1, "arcgraph: frame arcs name exactly one site");
    } else {
      require(named == 2 && a.left_site != a.right_site, "arcgraph: bisector arcs name two different sites");
    }
  }
  for (const Face& f : d.faces) {
    require(index_ok(f.site, d.sites.size(), false), "arcgraph: face sites in range");
    require(0 <= f.cycles_begin && f.cycles_begin <= f.cycles_end &&
                static_cast<std::size_t>(f.cycles_end) <= d.cycles.size(),
            "arcgraph: face cycle ranges in range");
  }
  for (const CycleRange& c : d.cycles) {
    require(0 <= c.begin && c.begin < c.end && static_cast<std::size_t>(c.end) <= d.half_arcs.size(),
            "arcgraph: cycles non-empty and in range");
  }
  for (const HalfArc& h : d.half_arcs) require(index_ok(h.arc, d.arcs.size(), false), "arcgraph: half-arcs in range");
  if (!d.clip.empty()) check_clip_polygon(d.clip, "arcgraph clip");
}

void check_coverage_map(const io::CoverageMap& map, bool planar) {
  require(!map.cells.empty(), "coverage map: at least one cell");
  std::size_t vertices = 0;
  for (const CoverageCell& cell : map.cells) {
    require(!cell.sensor.empty(), "coverage map: every cell names a sensor");
    require(!cell.polygons.empty(), "coverage map: every cell has a polygon");
    for (const CellPolygon& polygon : cell.polygons) {
      check_ring(polygon.outer, "coverage map outer ring");
      if (const auto tame = tame_scale(polygon.outer)) {
        require(turn_at_lowest(*tame) == 1, "coverage map outer ring", "counter-clockwise (judged at a tame scale)");
      }
      vertices += polygon.outer.size();
      for (const Ring& hole : polygon.holes) {
        check_ring(hole, "coverage map hole");
        if (const auto tame = tame_scale(hole)) {
          require(turn_at_lowest(*tame) == -1, "coverage map hole", "clockwise (judged at a tame scale)");
        }
        vertices += hole.size();
      }
    }
  }
  require(map.vertex_count == vertices, "coverage map: vertex_count is the number of vertices kept");
  if (planar) {
    require(!map.frame && map.max_scale_distortion == 0, "coverage map (planar): no projection");
  } else {
    require((map.frame != nullptr), "coverage map (lon/lat): a projection");
    require(finite(map.max_scale_distortion) && map.max_scale_distortion >= 0, "coverage map: distortion finite");
  }
}

void check_sensors(const std::vector<ReportedSensor>& sensors, bool geographic) {
  require(!sensors.empty(), "sensors: at least one sensor");
  std::set<std::string> ids;
  std::set<std::pair<double, double>> positions;  // as read
  for (const ReportedSensor& s : sensors) {
    require(!s.id.empty(), "sensors: ids are not empty");
    require(ids.insert(s.id).second, "sensors: ids are unique");
    require(finite(s.position), "sensors: positions are finite");
    require(s.weight && finite(*s.weight) && *s.weight > 0, "sensors: weight set, finite and > 0");
    require(!s.tx_power_dbm || finite(*s.tx_power_dbm), "sensors: powers finite");
    require(!s.position_sigma_m || (finite(*s.position_sigma_m) && *s.position_sigma_m > 0), "sensors: sigmas > 0");
    require(!s.power_sigma_db || (finite(*s.power_sigma_db) && *s.power_sigma_db > 0), "sensors: sigmas > 0");
    if (geographic) {
      require(s.lon && s.lat && std::abs(*s.lon) <= 180 && std::abs(*s.lat) <= 90, "sensors: lon/lat in range");
      require(positions.insert({*s.lon, *s.lat}).second, "sensors: no two sensors at the same lon/lat");
    } else {
      require(!s.lon && !s.lat, "sensors (planar map): no lon/lat");
      require(positions.insert({s.position.x, s.position.y}).second, "sensors: no two sensors at the same position");
    }
  }
}

}  // namespace covmap::fuzz
