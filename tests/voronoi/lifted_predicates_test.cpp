// The lifted-traits predicates must agree with CGAL's own predicates evaluated on the exactly
// lifted rational coordinates c = (x, y, -1/2)/w², ω = |c|² - (x²+y²)/w² — the oracle is CGAL's
// kernel over Gmpq, which shares no code with the homogeneous rewrites in lifted_traits.cpp.
#include <CGAL/Cartesian.h>
#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "voronoi/engine/lifted_traits.h"

namespace covmap::voronoi::engine {
namespace {

using Q = CGAL::Gmpq;
using QK = CGAL::Cartesian<Q>;

QK::Weighted_point_3 lift(const RawPoint& p) {
  const Q u = Q(1) / (Q(p.z()) * Q(p.z()));
  const QK::Point_3 c(Q(p.x()) * u, Q(p.y()) * u, Q(-1) / Q(2) * u);
  const Q omega = c.x() * c.x() + c.y() * c.y() + c.z() * c.z() -
                  (Q(p.x()) * Q(p.x()) + Q(p.y()) * Q(p.y())) * u;
  return {c, omega};
}

// Random points on a small grid with few weights, so that zero results (degeneracies) are common.
std::vector<RawPoint> grid_points(std::mt19937_64& rng, int count, bool coplanar_weights) {
  std::uniform_int_distribution<int> coord(-3, 3), weight(1, 3);
  std::vector<RawPoint> pts;
  for (int k = 0; k < count; ++k) {
    const double w = coplanar_weights ? 2.0 : static_cast<double>(weight(rng));
    pts.emplace_back(coord(rng) * 0.5, coord(rng) * 0.25, w);
  }
  return pts;
}

class LiftedPredicates : public ::testing::TestWithParam<bool> {};

TEST_P(LiftedPredicates, AgreeWithExactCgalOnLiftedPoints) {
  std::mt19937_64 rng(7);
  const QK k;
  int zeros_seen = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto p = grid_points(rng, 5, GetParam());
    std::array<QK::Weighted_point_3, 5> l;
    for (int i = 0; i < 5; ++i) l[i] = lift(p[i]);
    std::array<QK::Point_3, 5> b;
    for (int i = 0; i < 5; ++i) b[i] = l[i].point();

    EXPECT_EQ(lifted::orientation(p[0], p[1], p[2], p[3]),
              k.orientation_3_object()(b[0], b[1], b[2], b[3]));
    EXPECT_EQ(lifted::compare_xyz(p[0], p[1]), k.compare_xyz_3_object()(b[0], b[1]));
    const auto power5 = k.power_side_of_oriented_power_sphere_3_object()(l[0], l[1], l[2], l[3], l[4]);
    EXPECT_EQ(lifted::power_side(p[0], p[1], p[2], p[3], p[4]), power5);
    zeros_seen += power5 == CGAL::ON_ORIENTED_BOUNDARY;
    EXPECT_EQ(lifted::power_side(p[0], p[1]),
              k.power_side_of_oriented_power_sphere_3_object()(l[0], l[1]));
    // Lower-dimensional predicates are only defined on coplanar / collinear inputs.
    if (k.orientation_3_object()(b[0], b[1], b[2], b[3]) == CGAL::COPLANAR) {
      if (!k.collinear_3_object()(b[0], b[1], b[2])) {
        EXPECT_EQ(lifted::coplanar_orientation(p[0], p[1], p[2]),
                  k.coplanar_orientation_3_object()(b[0], b[1], b[2]));
        EXPECT_EQ(lifted::coplanar_orientation(p[0], p[1], p[2], p[3]),
                  k.coplanar_orientation_3_object()(b[0], b[1], b[2], b[3]));
        EXPECT_EQ(lifted::power_side(p[0], p[1], p[2], p[3]),
                  k.power_side_of_oriented_power_sphere_3_object()(l[0], l[1], l[2], l[3]));
      }
    }
    if (k.collinear_3_object()(b[0], b[1], b[2]) && b[0] != b[1]) {
      EXPECT_EQ(lifted::power_side(p[0], p[1], p[2]),
                k.power_side_of_oriented_power_sphere_3_object()(l[0], l[1], l[2]));
    }
  }
  EXPECT_GT(zeros_seen, 10) << "the grid should produce exact degeneracies";
}

// Off the grid, near-degenerate: five sites on a circle (equal weights, so the lifted points are
// nearly co-spherical) moved by a few ulps, at magnitudes where the semi-static power filter
// (lifted_traits.cpp) decides most signs by a margin of a few rounding errors. Its answer must be
// the exact one whenever it answers.
TEST(LiftedPredicates, PowerTestNearCoSphericalPointsIsExact) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(0, 6.283185307179586), centre(-1, 1);
  std::uniform_int_distribution<int> ulps(-4, 4), pick(0, 2);
  const double scales[] = {1.0, 1e-3, 1e5};
  int positive = 0, negative = 0, zero = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = scales[pick(rng)];
    const double cx = centre(rng) * scale, cy = centre(rng) * scale, r = 0.3 * scale;
    auto nudge = [&](double v) {
      for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) v = std::nextafter(v, k > 0 ? INFINITY : -INFINITY);
      return v;
    };
    std::array<RawPoint, 5> p;
    for (auto& q : p) {
      const double a = angle(rng);
      q = RawPoint(nudge(cx + r * std::cos(a)), nudge(cy + r * std::sin(a)), trial % 3 == 0 ? nudge(1.0) : 1.0);
    }
    std::array<QK::Weighted_point_3, 5> l;
    for (int i = 0; i < 5; ++i) l[i] = lift(p[i]);
    const auto exact = QK().power_side_of_oriented_power_sphere_3_object()(l[0], l[1], l[2], l[3], l[4]);
    ASSERT_EQ(lifted::power_side(p[0], p[1], p[2], p[3], p[4]), exact) << "trial " << trial;
    (exact > 0 ? positive : exact < 0 ? negative : zero) += 1;
  }
  EXPECT_GT(positive, 1000);
  EXPECT_GT(negative, 1000);
}

INSTANTIATE_TEST_SUITE_P(Weights, LiftedPredicates, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "EqualWeights" : "MixedWeights"; });

}  // namespace
}  // namespace covmap::voronoi::engine
