#include "io/polygon_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "io/text_util.h"

namespace covmap::io {
namespace {


// Error-free transformations: a*b == p + e and a+b == s + e exactly (Shewchuk 1997; the product
// needs a fused multiply-add).
void two_product(double a, double b, double& p, double& e) {
  p = a * b;
  e = std::fma(a, b, -p);
}

void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  e = (a - av) + (b - bv);
}

// Exact sign of the sum of `terms`, by growing a non-overlapping expansion one term at a time
// (Shewchuk's Grow-Expansion with zero elimination). The last non-zero component of the expansion
// has the largest magnitude and therefore carries the sign.
int exact_sign_of_sum(std::span<const double> terms) {
  std::vector<double> expansion;
  expansion.reserve(terms.size());
  for (const double term : terms) {
    double q = term;
    std::vector<double> grown;
    grown.reserve(expansion.size() + 1);
    for (const double h : expansion) {
      double sum = 0.0;
      double err = 0.0;
      two_sum(q, h, sum, err);
      if (err != 0.0) grown.push_back(err);
      q = sum;
    }
    if (q != 0.0) grown.push_back(q);
    expansion = std::move(grown);
  }
  if (expansion.empty()) return 0;
  return expansion.back() > 0 ? 1 : -1;
}

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

int orientation(Point a, Point b, Point c) {
  // Filter (Shewchuk's orient2d stage A): the rounded determinant has the right sign when its
  // magnitude exceeds (3 + 16 eps) eps times the sum of the magnitudes of its two products.
  const double left = (a.x - c.x) * (b.y - c.y);
  const double right = (a.y - c.y) * (b.x - c.x);
  const double det = left - right;
  constexpr double kEps = std::numeric_limits<double>::epsilon() / 2;  // unit roundoff
  constexpr double kBound = (3.0 + 16.0 * kEps) * kEps;
  if (std::abs(det) > kBound * (std::abs(left) + std::abs(right))) return sign(det);

  // Exact: expand the determinant into six products of input coordinates (no rounded differences)
  // and sum their exact two-double representations.
  const std::array<std::array<double, 2>, 6> products = {{{b.x, c.y}, {-b.y, c.x}, {-b.x, a.y},
                                                          {b.y, a.x}, {-a.x, c.y}, {a.y, c.x}}};
  std::array<double, 12> terms{};
  for (std::size_t i = 0; i < products.size(); ++i) two_product(products[i][0], products[i][1], terms[2 * i], terms[2 * i + 1]);
  return exact_sign_of_sum(terms);
}

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
