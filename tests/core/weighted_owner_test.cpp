// The kd-tree ownership queries must agree exactly with a linear scan written here.
#include "core/weighted_owner.h"

#include <gtest/gtest.h>

#include <random>

namespace covmap {
namespace {

std::vector<Site> random_sites(int n, double max_weight, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(-100, 100), w(1, max_weight);
  std::vector<Site> sites;
  for (int i = 0; i < n; ++i) sites.push_back(Site{"", pos(rng), pos(rng), w(rng)});
  return sites;
}

int scan_nearest(const std::vector<Site>& sites, Point p) {
  int best = kNone;
  double best_d = 0;
  for (int i = 0; i < static_cast<int>(sites.size()); ++i) {
    if (!site_is_valid(sites[i])) continue;
    const double d = std::hypot(p.x - sites[i].x, p.y - sites[i].y) / sites[i].weight;
    if (best == kNone || d < best_d) {
      best = i;
      best_d = d;
    }
  }
  return best;
}

TEST(WeightedOwner, NearestMatchesLinearScan) {
  std::mt19937_64 rng(7);
  for (const double max_weight : {1.0, 2.0, 50.0}) {
    const std::vector<Site> sites = random_sites(3000, max_weight, rng);
    const WeightedSiteIndex index(sites);
    std::uniform_real_distribution<double> q(-300, 300);
    for (int k = 0; k < 2000; ++k) {
      const Point p{q(rng), q(rng)};
      ASSERT_EQ(index.nearest(p), scan_nearest(sites, p)) << "max weight " << max_weight;
    }
  }
}

TEST(WeightedOwner, ForEachCloserVisitsExactlyTheCloserSites) {
  std::mt19937_64 rng(11);
  const std::vector<Site> sites = random_sites(2000, 5.0, rng);
  const WeightedSiteIndex index(sites);
  std::uniform_real_distribution<double> q(-150, 150), b(0, 20);
  for (int k = 0; k < 300; ++k) {
    const Point p{q(rng), q(rng)};
    const double bound = b(rng);
    std::vector<int> got, want;
    index.for_each_closer(p, bound, [&](int s, double) {
      got.push_back(s);
      return true;
    });
    for (int i = 0; i < static_cast<int>(sites.size()); ++i)
      if (std::hypot(p.x - sites[i].x, p.y - sites[i].y) / sites[i].weight < bound)
        want.push_back(i);
    std::sort(got.begin(), got.end());
    ASSERT_EQ(got, want);
  }
}

TEST(WeightedOwner, SkipsInvalidSitesAndBreaksTiesBySmallestIndex) {
  const std::vector<Site> sites = {Site{"", 0, 0, 0.0}, Site{"", 2, 0, 1}, Site{"", -2, 0, 1}};
  const WeightedSiteIndex index(sites);
  EXPECT_EQ(index.nearest({0, 0}), 1);  // site 0 has weight 0; 1 and 2 tie
  EXPECT_EQ(index.nearest({-1, 0}), 2);
  EXPECT_EQ(WeightedSiteIndex(std::vector<Site>{}).nearest({0, 0}), kNone);
}

TEST(WeightedOwner, BisectorOffsetIsSignedDistance) {
  const Site a{"", 0, 0, 1}, b{"", 2, 0, 1};
  EXPECT_NEAR(bisector_offset({0.75, 5}, a, b), -0.25, 1e-2);  // first order: exact at y = 0
  EXPECT_NEAR(bisector_offset({0.75, 0}, a, b), -0.25, 1e-15);
  EXPECT_NEAR(bisector_offset({1.5, 0}, a, b), 0.5, 1e-15);
  // A (0,0) w 1 vs B (3,0) w 2: the Apollonius circle centred (-1,0) with radius 2; (1 + t, 0) is
  // about t outside it, on B's side.
  const Site c{"", 0, 0, 1}, d{"", 3, 0, 2};
  EXPECT_NEAR(bisector_offset({1.001, 0}, c, d), 0.001, 1e-6);
  EXPECT_NEAR(bisector_offset({-1, 2}, c, d), 0.0, 1e-15);
}

TEST(WeightedOwner, BisectorOffsetStaysAccurateFarAway) {
  // Weights equal to 7 digits put the bisector circle's points 1e9 from the sites, where
  // |p - a| / wa - |p - b| / wb cancels to nothing in double. A point of that circle (computed in
  // long double, then rounded to double, i.e. moved by ~1e-7) must still measure as on it.
  const Site a{"", 0, 0, 1}, b{"", 100, 0, 1 + 1e-7};
  const long double wa = a.weight, wb = b.weight;
  const long double k = wa * wa / ((wa - wb) * (wa + wb));
  const long double cx = k * 100, r = wa * wb * 100 / std::abs((wa - wb) * (wa + wb));
  for (const long double angle : {0.3L, 2.0L, 3.0L}) {
    const Point p{static_cast<double>(cx + r * std::cos(angle)),
                  static_cast<double>(r * std::sin(angle))};
    ASSERT_GT(std::hypot(p.x, p.y), 1e8);
    EXPECT_LT(std::abs(bisector_offset(p, a, b)), 1e-5) << "angle " << static_cast<double>(angle);
  }
}

}  // namespace
}  // namespace covmap

namespace covmap {
namespace {

// Far from two equal-weight sites the bisector offset is, to first order, the distance to their
// perpendicular bisector, a closed form. The gradient as the difference of two unit vectors that
// agree to |b - a| / |p| would lose every digit at 1e15 or come out 0 ("inf off"), and every exact
// collinear diagram (nodes 1e15 out) would fail the checker.
TEST(BisectorOffset, FarFromEqualWeightSitesIsTheDistanceToTheirBisector) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    // Two sites of equal weight about 1 apart, a point `far` out along their bisector and `off`
    // off it.
    const Site a{"a", u(rng), u(rng), 2.0}, b{"b", u(rng), u(rng), 2.0};
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    const double nx = dx / len, ny = dy / len;  // unit normal of the bisector, towards b
    // Offsets well beyond the rounding of p (ε · far), so that a gradient off by 10% would show.
    const double far = std::pow(10.0, 3 + trial % 14), off = (0.25 + 1e-13 * far) * u(rng);
    const Point p{0.5 * (a.x + b.x) - ny * far + nx * off, 0.5 * (a.y + b.y) + nx * far + ny * off};
    const double exact = nx * (p.x - 0.5 * (a.x + b.x)) + ny * (p.y - 0.5 * (a.y + b.y));  // signed distance
    // First order: off² / far relative; the rounding of p (ε · far) absolute.
    EXPECT_NEAR(bisector_offset(p, a, b), exact, 1e-6 * std::abs(exact) + 1e-15 * far) << "trial " << trial << " far " << far;
  }
}

}  // namespace
}  // namespace covmap
