// polygon_defect: local checks in O(n), repeated vertices by sorting, and the sweep of
// io/segment_sweep.h for edges that meet. O(n log n) time, O(n) memory.
//
// Why the sweep finds every meeting of edges here (the sweep's own argument covers proper
// crossings only; touching needs this one). When the sweep runs, the ring has at least 3 vertices,
// all finite and pairwise distinct, and no two consecutive edges overlap (double back). Then two
// consecutive edges meet exactly at their shared vertex, and the defects are the "bad" pairs:
// non-consecutive edges that meet. The sweep accepts exactly the bad pairs; a properly crossing pair
// is bad, so find_adjacent_pair's precondition holds, and (G), (C), (N) of io/segment_sweep.h apply.
// Suppose a bad pair exists; let X be the first point (lexicographically) that lies on both edges
// of a bad pair. Vertices are distinct, so at most two edges end at X, and if two, they are the two
// edges of the vertex X, which are consecutive; so one edge of the bad pair, P, has X in its
// relative interior. Any other edge E through X forms a bad pair with P: were they consecutive,
// they would meet at their shared vertex and at X, which is not a vertex of P, so they would
// overlap. No proper crossing comes before X (it would be an earlier bad point). Let T be the edges
// through X that begin before X (P is one). If the sweep has not stopped before:
//   - T has another member: T is a contiguous run of the status after the last event before X, in
//     order (C, G), so P has a neighbour in T there; that pair is bad and was tested (N).
//   - T = {P}: the other edge of the bad pair begins at X, so X is a vertex and both its edges begin
//     there (an edge ending at X would be in T). No removal happens at X, and no two edges of the
//     status cross properly at X (only P has X inside), so by (G) the first insertion at X, E,
//     searches an ordered status and lands in the order just after X. An edge between P and E just
//     after X would be squeezed towards X, hence contain X, hence be the other edge of the vertex,
//     not yet inserted: E lands next to P and the bad pair (P, E) is tested.
// So the sweep accepts a bad pair whenever there is one, and it accepts nothing else: the ring is
// simple exactly when the sweep finds nothing.
#include "io/polygon_check.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "core/orientation.h"
#include "core/round_trip_numbers.h"
#include "io/segment_sweep.h"
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
  return std::to_string(i) + " (" + round_trip_number(ring[i].x) + ", " + round_trip_number(ring[i].y) + ")";
}

std::string edge(std::span<const Point> ring, std::size_t i) {
  return "edge " + vertex(ring, i) + " -> " + vertex(ring, (i + 1) % ring.size());
}

// A vertex visited twice: the same point at two places of the ring (never consecutive ones, which
// polygon_defect rejects before). Names the lexicographically first such point, by its first two
// indices. O(n log n).
std::optional<std::string> repeated_vertex(std::span<const Point> ring) {
  std::vector<std::size_t> by_point(ring.size());
  std::iota(by_point.begin(), by_point.end(), std::size_t{0});
  std::sort(by_point.begin(), by_point.end(), [&](std::size_t i, std::size_t j) {
    const Point p = ring[i], q = ring[j];
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    return i < j;
  });
  for (std::size_t k = 1; k < by_point.size(); ++k) {
    const Point p = ring[by_point[k - 1]], q = ring[by_point[k]];
    if (p.x == q.x && p.y == q.y) {
      return "the polygon is not simple: vertex " + vertex(ring, by_point[k - 1]) + " and vertex " +
             vertex(ring, by_point[k]) + " are the same point";
    }
  }
  return std::nullopt;
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
  if (auto repeated = repeated_vertex(ring)) return repeated;

  std::vector<detail::Segment> edges(n);
  for (std::size_t i = 0; i < n; ++i) edges[i] = {ring[i], ring[(i + 1) % n]};
  const auto consecutive = [n](std::size_t i, std::size_t j) { return j == i + 1 || (i == 0 && j == n - 1); };
  const auto meeting = detail::find_adjacent_pair(std::move(edges), [&](std::size_t i, std::size_t j) {
    return !consecutive(i, j) && segments_meet(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n]);
  });
  if (meeting) return "the polygon is not simple: " + edge(ring, meeting->first) + " meets " + edge(ring, meeting->second);
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
