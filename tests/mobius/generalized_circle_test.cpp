// Generalized circles read from their forms: distance, nearest point and intersections of circles
// of radius up to 1e14 near the origin, against points constructed to lie on them (closed forms).
// Why from the forms: reading a centre and radius off a circle of radius R loses R·ε, ~1e-4 at
// R = 1e12, where recognition needs 1e-5 of an extent of 100 (nearly equal weights).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mobius/generalized_circle.h"

namespace covmap::mobius {
namespace {

// The circle through 0 and p whose normal at 0 is n (unit): A|z|² + 2Re(conj(B) z) = 0 with B = n
// and A = -2Re(conj(n) p)/|p|²; huge when n is nearly perpendicular to p.
GeneralizedCircle through_origin_and(Complex p, Complex n) {
  return {-2.0 * std::real(std::conj(n) * p) / std::norm(p), n, 0.0};
}

TEST(GeneralizedCircle, HugeCirclesAreMeasuredAndMetWhereTheirFormsSay) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Complex p(100 * u(rng), 100 * u(rng));
    const double tilt = std::pow(10.0, -4 - 10 * (u(rng) + 1) / 2);  // radius ~|p| / tilt: up to 1e16
    const Complex across = Complex(0, 1) * p / std::abs(p);
    const GeneralizedCircle a = through_origin_and(p, across * std::polar(1.0, tilt));
    const GeneralizedCircle b = through_origin_and(p, across * std::polar(1.0, -2 * tilt - 0.3 * u(rng)));
    const double allowed = 1e-12 * std::abs(p);
    EXPECT_LE(distance_to(a, p), allowed) << trial;
    EXPECT_LE(std::abs(nearest_point(a, p) - p), allowed) << trial;
    // A point off the circle by a known amount along its normal at 0 (the origin lies on it).
    EXPECT_NEAR(distance_to(a, 0.5 * a.B), 0.5, 1e-12) << trial;
    EXPECT_LE(std::abs(nearest_point(a, 0.5 * a.B)), 1e-12) << trial;
    const auto points = intersect(a, b);
    ASSERT_EQ(points.size(), 2u) << trial;
    const double to_p = std::min(std::abs(points[0] - p), std::abs(points[1] - p));
    const double to_0 = std::min(std::abs(points[0]), std::abs(points[1]));
    EXPECT_LE(to_p, allowed) << trial;
    EXPECT_LE(to_0, allowed) << trial;
  }
}

}  // namespace
}  // namespace covmap::mobius
