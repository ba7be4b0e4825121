#include "io/coverage_map_rings.h"

#include <algorithm>
#include <cstdint>

#include "core/round_trip_numbers.h"
#include "io/coverage_map_crossings.h"
#include "io/polygon_check.h"
#include "io/text_util.h"

namespace covmap::io::detail {
namespace {


bool same(Point p, Point q) { return p.x == q.x && p.y == q.y; }

// A ring without repeats, and for each kept vertex its position index in the file.
struct CleanRing {
  std::vector<Point> points;
  std::vector<std::uint32_t> source;
};

CleanRing clean(const RingInput& ring) {
  CleanRing out;
  const auto& p = ring.projected;
  // The last position repeats the first (checked when the ring was read), so it is never kept.
  const std::size_t n = p.empty() ? 0 : p.size() - 1;
  out.points.reserve(n);
  out.source.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!out.points.empty() && same(out.points.back(), p[i])) continue;
    out.points.push_back(p[i]);
    out.source.push_back(static_cast<std::uint32_t>(i));
  }
  // Repeats of the first vertex at the end (…, a, a] before the closing a): the same point twice.
  while (out.points.size() > 1 && same(out.points.back(), out.points.front())) {
    out.points.pop_back();
    out.source.pop_back();
  }
  return out;
}

// "position 7 (8.01, 47.2)": the index and the coordinates as they are in the file.
std::string position(const RingInput& ring, std::uint32_t index) {
  const Point p = ring.read[index];
  return "position " + std::to_string(index) + " (" + round_trip_number(p.x) + ", " + round_trip_number(p.y) + ")";
}

// "the edge from position 3 (…) to position 4 (…)"; source maps the kept vertices to file positions.
std::string edge_text(const RingInput& ring, const std::vector<std::uint32_t>& source, std::size_t edge) {
  const std::size_t next = (edge + 1) % source.size();
  return "the edge from " + position(ring, source[edge]) + " to " + position(ring, source[next]);
}

// The turn at the lowest (then leftmost) vertex, where any ring is locally convex: its sign is the
// ring's orientation. 0 when the ring doubles back there or lies on one line; `problems` says which.
int orientation_at_lowest(const RingInput& ring, const CleanRing& c, const std::string& name,
                          std::vector<std::string>& problems) {
  const auto& p = c.points;
  const std::size_t n = p.size();
  std::size_t low = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (p[i].y < p[low].y || (p[i].y == p[low].y && p[i].x < p[low].x)) low = i;
  }
  const int turn = orientation(p[(low + n - 1) % n], p[low], p[(low + 1) % n]);
  if (turn != 0) return turn;
  bool on_one_line = true;
  for (std::size_t i = 2; i < n && on_one_line; ++i) on_one_line = orientation(p[0], p[1], p[i]) == 0;
  if (on_one_line) {
    problems.push_back(name + " has zero area (all " + std::to_string(n) + " distinct vertices lie on one line)");
  } else {
    problems.push_back(name + " doubles back on itself at " + position(ring, c.source[low]) +
                       " (the edges before and after it overlap)");
  }
  return 0;
}

}  // namespace

std::string ring_name(const PolygonPlace& place, std::size_t ring) {
  const std::string name = ring == 0 ? "outer ring" : "hole " + std::to_string(ring);
  return place.multi ? name + " of polygon " + std::to_string(place.polygon) : name;
}

std::optional<MapPolygon> make_map_polygon(const std::vector<RingInput>& rings, const PolygonPlace& place,
                                           std::vector<std::string>& problems) {
  const std::size_t problems_before = problems.size();
  std::vector<CleanRing> clean_rings;
  std::vector<int> orientations;
  clean_rings.reserve(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    clean_rings.push_back(clean(rings[r]));
    const CleanRing& c = clean_rings.back();
    const std::string name = ring_name(place, r);
    if (c.points.size() < 3) {
      problems.push_back(name + " has " + std::to_string(c.points.size()) +
                         " distinct vertices; a ring needs at least 3");
      orientations.push_back(0);
      continue;
    }
    orientations.push_back(orientation_at_lowest(rings[r], c, name, problems));
  }
  if (problems.size() > problems_before) return std::nullopt;

  std::vector<std::vector<Point>> points;
  points.reserve(clean_rings.size());
  for (auto& c : clean_rings) points.push_back(std::move(c.points));
  if (const auto crossing = find_crossing(points)) {
    const auto [a, b] = *crossing;
    const auto edge_a = edge_text(rings[a.ring], clean_rings[a.ring].source, a.edge);
    const auto edge_b = edge_text(rings[b.ring], clean_rings[b.ring].source, b.edge);
    if (a.ring == b.ring) {
      problems.push_back(ring_name(place, a.ring) + " crosses itself: " + edge_a + " crosses " + edge_b);
    } else {
      // "the outer ring", but "hole 2".
      const auto the = [&](std::size_t r) { return (r == 0 ? "the " : "") + ring_name(place, r); };
      problems.push_back(ring_name(place, b.ring) + " crosses " + the(a.ring) + ": " + edge_a + " of " + the(a.ring) +
                         " crosses " + edge_b + " of " + the(b.ring));
    }
    return std::nullopt;
  }

  MapPolygon polygon;
  for (std::size_t r = 0; r < points.size(); ++r) {
    const int wanted = r == 0 ? 1 : -1;  // outer counter-clockwise, holes clockwise
    if (orientations[r] != wanted) std::reverse(points[r].begin(), points[r].end());
    if (r == 0) polygon.outer = std::move(points[r]);
    else polygon.holes.push_back(std::move(points[r]));
  }
  return polygon;
}

}  // namespace covmap::io::detail
