// fitting::local_uncertainty against oracles computed here:
//  - a closed form: equal-weight sites whose samples lie (up to a tiny offset) on the straight
//    bisectors x = 1 and y = 1 of a centre site at the origin; there each sample's gradient with
//    respect to the centre's (x, y, u) is known in closed form (below), every residual is ±δ, so the
//    robust noise level is 1.4826 δ and every Cauchy weight is 1 / (1 + (1 / (1.4826 c))²);
//  - a finite-difference JᵀJ: the residual written out again from its definition in
//    fitting/residuals.h, differentiated by central differences, weighted as the header says,
//    on unequal weights with irregular offsets and an outlier;
//  - the undetermined cases: exact samples (no noise), one neighbour only, too few samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fitting/local_uncertainty.h"
#include "fitting/tolerances.h"

namespace covmap::fitting {
namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 inverse(const Mat3& m) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  Mat3 inv;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
      inv[i][j] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;  // cofactor transpose
    }
  return inv;
}

void add_outer(Mat3& m, const Vec3& g, double w) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] += w * g[i] * g[j];
}

// What the header promises, from a 3×3 information block and the noise level.
LocalUncertainty expected_from(const Mat3& info, double noise) {
  const Mat3 inv = inverse(info);
  const double n2 = noise * noise;
  return {std::sqrt(n2 * inv[0][0]), std::sqrt(n2 * inv[1][1]), n2 * inv[0][1], std::sqrt(n2 * inv[2][2]), true};
}

void expect_close(const LocalUncertainty& got, const LocalUncertainty& want, double rel, const char* what) {
  ASSERT_TRUE(got.available) << what;
  EXPECT_NEAR(got.sigma_x, want.sigma_x, rel * want.sigma_x) << what;
  EXPECT_NEAR(got.sigma_y, want.sigma_y, rel * want.sigma_y) << what;
  EXPECT_NEAR(got.cov_xy, want.cov_xy, rel * want.sigma_x * want.sigma_y) << what;
  EXPECT_NEAR(got.sigma_log_weight, want.sigma_log_weight, rel * want.sigma_log_weight) << what;
}

// Centre site 0 at the origin, neighbours 1 at (2, 0) and 2 at (0, 2), all weight 1. Samples on
// x = 1 (bisector 0|1) at the given y and on y = 1 (bisector 0|2) at the given x, each moved off
// its bisector by ±delta, alternately (site_a = 0 always).
std::vector<BoundarySample> cross_samples(const std::vector<double>& along, double delta) {
  std::vector<BoundarySample> s;
  int sign = 1;
  for (double t : along) {
    s.push_back({{1.0 + sign * delta, t}, 0, 1, 1.0, 0});
    sign = -sign;
  }
  for (double t : along) {
    s.push_back({{t, 1.0 + sign * delta}, 0, 2, 1.0, 1});
    sign = -sign;
  }
  return s;
}

const std::vector<Site> kCross{{"c", 0, 0, 1}, {"e", 2, 0, 1}, {"n", 0, 2, 1}};

TEST(LocalUncertainty, ClosedFormOnStraightBisectors) {
  // On x = 1, between a = (0, 0) and b = (2, 0) with k = 1, at p = (1, y): f = 0, ∇_p f = (2/D, 0)
  // with D = √(1 + y²), and ∂r/∂(a_x, a_y, u_a) = ∂f/∂(…) / |∇_p f| = (−1/2, −y/2, −D²/2). On
  // y = 1 (partner (0, 2)) at p = (x, 1), by symmetry: (−x/2, −1/2, −(1 + x²)/2).
  const std::vector<double> along{-2.0, -1.3, -0.4, 0.5, 1.1, 1.9, 3.0};  // 14 samples in all
  const double delta = 1e-7, loss_scale = 2.0;
  const auto samples = cross_samples(along, delta);
  // |r| = δ for every sample (to O(δ²)): median δ, noise 1.4826 δ; every u = r / (c · noise) has
  // |u| = 1 / (1.4826 c).
  const double noise = 1.4826 * delta;
  const double u = 1.0 / (1.4826 * loss_scale);
  const double w = 1.0 / (1.0 + u * u);
  Mat3 info{};
  for (double y : along) add_outer(info, {-0.5, -0.5 * y, -0.5 * (1 + y * y)}, w);
  for (double x : along) add_outer(info, {-0.5 * x, -0.5, -0.5 * (1 + x * x)}, w);
  const auto got = local_uncertainty(kCross, samples, loss_scale);
  ASSERT_EQ(got.size(), 3u);
  expect_close(got[0], expected_from(info, noise), 1e-5, "centre");
  // The neighbours border only the centre: along one boundary a site slides with its weight.
  EXPECT_FALSE(got[1].available);
  EXPECT_FALSE(got[2].available);
}

TEST(LocalUncertainty, SigmaScalesWithTheNoiseLevel) {
  // Offsets ten times larger: every σ ten times larger (the gradients change only to O(δ)).
  const std::vector<double> along{-2.0, -0.7, 0.3, 1.6, 2.4};
  const auto small = local_uncertainty(kCross, cross_samples(along, 1e-7), 1.0);
  const auto large = local_uncertainty(kCross, cross_samples(along, 1e-6), 1.0);
  ASSERT_TRUE(small[0].available && large[0].available);
  EXPECT_NEAR(large[0].sigma_x / small[0].sigma_x, 10.0, 1e-4);
  EXPECT_NEAR(large[0].sigma_log_weight / small[0].sigma_log_weight, 10.0, 1e-4);
}

// ---------------------------------------------------------------------------------------------
// Finite-difference oracle.

// The residual of fitting/residuals.h, written out again: f = |p − a| − k |p − b|, k = e^{u_a − u_b},
// r = f / √(|∇_p f|² + (floor (1 + k))²), scale 1.
double residual(Point p, const std::array<double, 6>& q) {
  const double ax = p.x - q[0], ay = p.y - q[1], bx = p.x - q[3], by = p.y - q[4];
  const double da = std::hypot(ax, ay), db = std::hypot(bx, by);
  const double k = std::exp(q[2] - q[5]);
  const double gx = ax / da - k * bx / db, gy = ay / da - k * by / db;
  const double fl = tolerance::kGradientFloor * (1 + k);
  return (da - k * db) / std::sqrt(gx * gx + gy * gy + fl * fl);
}

std::array<double, 6> gradient(Point p, const std::array<double, 6>& q) {
  std::array<double, 6> g{};
  for (int i = 0; i < 6; ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(q[i]));
    auto plus = q, minus = q;
    plus[i] += h, minus[i] -= h;
    g[i] = (residual(p, plus) - residual(p, minus)) / (2 * h);
  }
  return g;
}

// Per site, the header's recipe: noise 1.4826 · median |r| (odd count), Cauchy weights at
// loss_scale · noise, the site's 3×3 block of Σ w g gᵀ.
std::vector<Mat3> fd_information(const std::vector<Site>& sites, const std::vector<BoundarySample>& samples,
                                 double loss_scale, double* noise) {
  std::vector<double> r, abs_r;
  for (const auto& s : samples) {
    const Site& a = sites[s.site_a];
    const Site& b = sites[s.site_b];
    r.push_back(residual(s.p, {a.x, a.y, std::log(a.weight), b.x, b.y, std::log(b.weight)}));
    abs_r.push_back(std::abs(r.back()));
  }
  std::sort(abs_r.begin(), abs_r.end());
  *noise = 1.4826 * abs_r[abs_r.size() / 2];
  std::vector<Mat3> info(sites.size(), Mat3{});
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& s = samples[k];
    const Site& a = sites[s.site_a];
    const Site& b = sites[s.site_b];
    const auto g = gradient(s.p, {a.x, a.y, std::log(a.weight), b.x, b.y, std::log(b.weight)});
    const double u = r[k] / (loss_scale * *noise);
    const double w = 1.0 / (1.0 + u * u);
    add_outer(info[s.site_a], {g[0], g[1], g[2]}, w);
    add_outer(info[s.site_b], {g[3], g[4], g[5]}, w);
  }
  return info;
}

// Points on the Apollonius circle of a and b (weights ≠), moved radially by the given offsets.
void add_on_bisector(const std::vector<Site>& sites, int a, int b, const std::vector<double>& angles,
                     const std::vector<double>& offsets, std::vector<BoundarySample>& out) {
  const Site& A = sites[a];
  const Site& B = sites[b];
  const double k = A.weight / B.weight;
  const double cx = (A.x - k * k * B.x) / (1 - k * k), cy = (A.y - k * k * B.y) / (1 - k * k);
  const double R = k * std::hypot(A.x - B.x, A.y - B.y) / std::abs(1 - k * k);
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double rr = R + offsets[i % offsets.size()];
    out.push_back({{cx + rr * std::cos(angles[i]), cy + rr * std::sin(angles[i])}, a, b, 0.5, 0});
  }
}

TEST(LocalUncertainty, MatchesFiniteDifferenceInformationOnUnequalWeights) {
  const std::vector<Site> sites{{"0", 0, 0, 0.6}, {"1", 10, 1, 1.0}, {"2", 3, 9, 0.9}, {"3", -6, 5, 1.3}};
  std::vector<BoundarySample> samples;
  const std::vector<double> offsets{0.03, -0.05, 0.01, -0.02, 0.04, -0.01, 0.02};
  add_on_bisector(sites, 0, 1, {-0.8, -0.5, -0.2, 0.1, 0.4, 0.7}, offsets, samples);
  add_on_bisector(sites, 2, 0, {3.6, 3.9, 4.2, 4.5, 4.8}, offsets, samples);
  add_on_bisector(sites, 0, 3, {2.2, 2.5, 2.8, 3.1, 3.4, 3.7}, offsets, samples);
  add_on_bisector(sites, 1, 2, {0.5, 1.0, 1.5, 2.0}, offsets, samples);
  samples.back().p.x += 2.0;  // an outlier, which the Cauchy weight discounts
  ASSERT_EQ(samples.size() % 2, 1u) << "odd, so that the median is one sample's";
  for (double loss_scale : {1.0, 3.0}) {
    double noise = 0;
    const auto info = fd_information(sites, samples, loss_scale, &noise);
    ASSERT_GT(noise, 0.0);
    const auto got = local_uncertainty(sites, samples, loss_scale);
    ASSERT_EQ(got.size(), 4u);
    // Sites 0, 1 and 2 border two others; site 3 only site 0.
    expect_close(got[0], expected_from(info[0], noise), 1e-5, "site 0");
    expect_close(got[1], expected_from(info[1], noise), 1e-5, "site 1");
    expect_close(got[2], expected_from(info[2], noise), 1e-5, "site 2");
    EXPECT_FALSE(got[3].available);
  }
}

TEST(LocalUncertainty, ExactSamplesHaveNoNoiseLevelAndAreUnavailable) {
  // On the bisectors exactly: every residual 0, the noise level 0, nothing to scale by.
  std::vector<BoundarySample> samples;
  for (double t : {-1.0, 0.0, 1.0, 2.0}) {
    samples.push_back({{1.0, t}, 0, 1, 1.0, 0});
    samples.push_back({{t, 1.0}, 0, 2, 1.0, 1});
  }
  for (const auto& u : local_uncertainty(kCross, samples, 1.0)) EXPECT_FALSE(u.available);
}

TEST(LocalUncertainty, TooFewSamplesForAFullRankBlockAreUnavailable) {
  // One sample on each of two bisectors: two neighbours, but a rank-2 block of a 3×3 problem.
  const auto got = local_uncertainty(kCross, cross_samples({0.5}, 1e-3), 1.0);
  for (const auto& u : got) EXPECT_FALSE(u.available);
}

TEST(LocalUncertainty, SitesWithoutSamplesAreUnavailable) {
  std::vector<Site> sites = kCross;
  sites.push_back({"far", 50, 50, 1});
  const auto got = local_uncertainty(sites, cross_samples({-1.0, 0.0, 0.7, 1.5, 2.5}, 1e-4), 1.0);
  ASSERT_EQ(got.size(), 4u);
  EXPECT_TRUE(got[0].available);
  EXPECT_FALSE(got[3].available);
  for (const auto& u : local_uncertainty(sites, std::vector<BoundarySample>{}, 1.0)) EXPECT_FALSE(u.available);
}

}  // namespace
}  // namespace covmap::fitting
