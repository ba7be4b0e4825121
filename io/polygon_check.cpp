#include "io/polygon_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "core/orientation.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

int sign(double v) { return (v > 0) - (v < 0); }

bool on_segment_box(Point a, Point b, Point p) {
  // p is known to be collinear with a, b; it is on the segment iff inside the bounding box.
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Closed segments [p1,p2] and [q1,q2] share at least one point.
bool segments_meet(Point p1, Point p2, Point q1, Point q2) {
  const int o1 = orientation(p1, p2, q1);
  const int o2 = orientation(p1, p2, q2);
  const int o3 = orientation(q1, q2, p1);
  const int o4 = orientation(q1, q2, p2);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_segment_box(p1, p2, q1)) || (o2 == 0 && on_segment_box(p1, p2, q2)) ||
         (o3 == 0 && on_segment_box(q1, q2, p1)) || (o4 == 0 && on_segment_box(q1, q2, p2));
}

// Edges a-b and b-c overlap (the ring doubles back on itself at b). Exact: for collinear points,
// "a and c lie on the same side of b" is a comparison of coordinates.
bool doubles_back(Point a, Point b, Point c) {
  if (orientation(a, b, c) != 0) return false;
  const int ax = sign(a.x - b.x), cx = sign(c.x - b.x);
  if (ax != 0 || cx != 0) return ax == cx;
  return sign(a.y - b.y) == sign(c.y - b.y);
}

std::string vertex(std::span<const Point> ring, std::size_t i) {
  return std::to_string(i) + " (" + detail::format_number(ring[i].x) + ", " + detail::format_number(ring[i].y) + ")";
}

std::string edge(std::span<const Point> ring, std::size_t i) {
  return "edge " + vertex(ring, i) + " -> " + vertex(ring, (i + 1) % ring.size());
}

}  // namespace

std::optional<std::string> polygon_defect(std::span<const Point> ring) {
  const std::size_t n = ring.size();
  if (n < 3) return "a polygon needs at least 3 vertices (got " + std::to_string(n) + ")";
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y)) return "vertex " + vertex(ring, i) + " is not finite";
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n];
    if (a.x == b.x && a.y == b.y) return "vertex " + vertex(ring, (i + 1) % n) + " repeats the vertex before it";
  }
  bool all_collinear = true;
  for (std::size_t i = 2; i < n && all_collinear; ++i) all_collinear = orientation(ring[0], ring[1], ring[i]) == 0;
  if (all_collinear) return "the polygon has zero area (all vertices are collinear)";

  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n], c = ring[(i + 2) % n];
    if (doubles_back(a, b, c)) return edge(ring, i) + " and the next edge overlap";
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // consecutive through the closing vertex
      if (segments_meet(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) {
        return "the polygon is not simple: " + edge(ring, i) + " meets " + edge(ring, j);
      }
    }
  }
  return std::nullopt;
}

int ring_orientation(std::span<const Point> ring) {
  // At the lowest (then leftmost) vertex the ring is locally convex, so the turn there is the
  // orientation of the whole ring, and it is never collinear for a valid polygon.
  std::size_t low = 0;
  for (std::size_t i = 1; i < ring.size(); ++i) {
    if (ring[i].y < ring[low].y || (ring[i].y == ring[low].y && ring[i].x < ring[low].x)) low = i;
  }
  const std::size_t n = ring.size();
  return orientation(ring[(low + n - 1) % n], ring[low], ring[(low + 1) % n]);
}

}  // namespace covmap::io
