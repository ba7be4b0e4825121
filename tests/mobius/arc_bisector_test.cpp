// Lemma 1 relative to a point on the arc (bisector_relation.h, ArcBisector) against the exact
// inversion in rational arithmetic (CGAL::Gmpq): for circles of every size, up to radii 10^9 times
// the sites' distance from the arc (weight ratios 1 + 10^-9), where the plane-coordinate formula
// c + r²/conj(p - c) has lost most of its digits.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <cmath>
#include <random>

#include "mobius/bisector_relation.h"

namespace covmap::mobius {
namespace {

using Q = CGAL::Gmpq;

// The exact inversion of p in the circle through v with centre c (all doubles, taken exactly).
Complex exact_inversion(Complex c, Complex v, Complex p) {
  const Q cx(c.real()), cy(c.imag()), vx(v.real()), vy(v.imag()), px(p.real()), py(p.imag());
  const Q r2 = (vx - cx) * (vx - cx) + (vy - cy) * (vy - cy);
  const Q dx = px - cx, dy = py - cy;
  const Q d2 = dx * dx + dy * dy;
  const Q ix = cx + r2 * dx / d2, iy = cy + r2 * dy / d2;
  return {CGAL::to_double(ix), CGAL::to_double(iy)};
}

Arc circle_arc(Complex centre, double r, int from) {
  Arc a;
  a.from = a.to = from;
  a.curve = Circle{centre.real(), centre.imag(), r};
  return a;
}

TEST(ArcBisector, PartnerIsTheExactInversionForCirclesOfEverySize) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(0.0, 6.283185307179586);
  double worst_node_frame = 0, worst_plane = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double radius = std::pow(10.0, -2.0 + 11.0 * (trial % 40) / 39.0);  // 1e-2 .. 1e9
    const Complex v(u(rng), u(rng));
    const Complex centre = v - std::polar(radius, angle(rng));
    const Complex p = v + 0.3 * Complex(u(rng), u(rng));  // a site near the arc's node
    const std::vector<Node> nodes = {{v.real(), v.imag()}};
    const Arc arc = circle_arc(centre, std::abs(centre - v), 0);
    const Complex truth = exact_inversion(centre, v, p);
    const double scale = std::abs(truth - v) + std::abs(p - v);  // the size of what is computed
    const WeightedPoint node_frame = partner_across(arc_bisector(arc, nodes), {p, 1.0});
    const WeightedPoint plane = partner_across(GeneralizedCircle::circle(centre, std::abs(centre - v)), {p, 1.0});
    worst_node_frame = std::max(worst_node_frame, std::abs(node_frame.position - truth) / scale);
    worst_plane = std::max(worst_plane, std::abs(plane.position - truth) / scale);
    // Lemma 1: w_partner / w = r / |c - p|, and |c - p| |c - partner| = r².
    const double r = std::abs(centre - v);
    EXPECT_NEAR(node_frame.weight, r / std::abs(centre - p), 1e-12 * node_frame.weight) << "radius " << radius;
  }
  EXPECT_LT(worst_node_frame, 1e-13);
  // The reason for the node frame: the plane formula is far worse for the huge circles.
  EXPECT_GT(worst_plane, 1e3 * worst_node_frame);
}

TEST(ArcBisector, LinesAreMirrorsAndSidesAreStrict) {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Complex a(u(rng), u(rng)), b(u(rng), u(rng));
    std::vector<Node> nodes = {{a.real(), a.imag()}, {b.real(), b.imag()}};
    Arc arc;
    arc.from = 0, arc.to = 1;
    arc.curve = Line{a.real(), a.imag(), (b - a).real(), (b - a).imag()};
    const ArcBisector bis = arc_bisector(arc, nodes);
    const Complex p(u(rng), u(rng));
    const WeightedPoint m = partner_across(bis, {p, 2.0});
    // The mirror image: same distance to both ends, the midpoint on the line.
    EXPECT_NEAR(std::abs(m.position - a), std::abs(p - a), 1e-12);
    EXPECT_NEAR(std::abs(m.position - b), std::abs(p - b), 1e-12);
    EXPECT_EQ(m.weight, 2.0);
    const double cross = std::imag(std::conj(b - a) * (p - a));  // > 0: p left of a -> b
    if (std::abs(cross) > 1e-9) {
      EXPECT_EQ(strictly_inside(bis, p), cross > 0);
      EXPECT_NE(strictly_inside(bis, p), strictly_inside(bis, m.position));
    }
  }
  // A circle: inside is the disk.
  const std::vector<Node> nodes = {{1.0, 0.0}};
  Arc arc = circle_arc({0.0, 0.0}, 1.0, 0);
  const ArcBisector bis = arc_bisector(arc, nodes);
  EXPECT_TRUE(strictly_inside(bis, {0.5, 0.2}));
  EXPECT_FALSE(strictly_inside(bis, {1.5, 0.2}));
  EXPECT_FALSE(strictly_inside(bis, {1.0, 0.0}));
}

}  // namespace
}  // namespace covmap::mobius
