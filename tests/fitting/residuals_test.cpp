// The boundary residual against closed forms: the exact distance to the Apollonius circle (and to
// the perpendicular bisector for equal weights) to first order, and smoothness through k = 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fitting/residuals.h"

namespace covmap::fitting {
namespace {

double residual_at(double px, double py, const double a[3], const double b[3]) {
  double r = 0.0;
  BoundaryResidual(px, py, 1.0)(a, b, &r);
  return r;
}

// Largest |residual − signed exact distance| over points q + t n, q around the whole Apollonius
// circle of (a, wa), (b, wb), n its outward normal. Inside the circle is the lighter site's side.
double circle_error(double t, double wa, double wb) {
  const double a[3] = {0.0, 0.0, std::log(wa)}, b[3] = {1.0, 0.3, std::log(wb)};
  const double k = wa / wb;
  const double cx = (a[0] - k * k * b[0]) / (1 - k * k), cy = (a[1] - k * k * b[1]) / (1 - k * k);
  const double radius = k * std::hypot(b[0] - a[0], b[1] - a[1]) / std::abs(1 - k * k);
  // Lighter site inside: with wa > wb that is b, whose side is positive, so the residual ≈ −t.
  const double sign = wa > wb ? -1.0 : 1.0;
  double worst = 0.0;
  for (int i = 0; i < 360; ++i) {
    const double theta = 2 * std::numbers::pi * i / 360;
    const double nx = std::cos(theta), ny = std::sin(theta);
    const double px = cx + (radius + t) * nx, py = cy + (radius + t) * ny;
    worst = std::max(worst, std::abs(residual_at(px, py, a, b) - sign * t));
  }
  return worst;
}

TEST(BoundaryResidual, MatchesApolloniusDistanceToFirstOrder) {
  for (const auto& [wa, wb] : {std::pair(1.3, 1.0), std::pair(1.0, 2.5), std::pair(1.05, 1.0)}) {
    for (double sign : {1.0, -1.0}) {
      const double coarse = circle_error(sign * 1e-2, wa, wb);
      const double fine = circle_error(sign * 1e-3, wa, wb);
      // Second order: the error shrinks ~100× for a 10× smaller offset and stays well below t.
      EXPECT_LT(coarse, 0.05 * 1e-2) << wa << " " << wb;
      EXPECT_GT(coarse / fine, 50.0) << wa << " " << wb;
      EXPECT_LT(circle_error(0.0, wa, wb), 1e-12) << "points on the circle have residual 0";
    }
  }
}

TEST(BoundaryResidual, EqualWeightsIsDistanceToPerpendicularBisector) {
  const double a[3] = {0.2, -0.1, 0.7}, b[3] = {1.4, 0.8, 0.7};
  const double ux = b[0] - a[0], uy = b[1] - a[1], len = std::hypot(ux, uy);
  const double mx = 0.5 * (a[0] + b[0]), my = 0.5 * (a[1] + b[1]);
  for (double s : {-2.0, -0.3, 0.0, 0.5, 3.0}) {
    for (double t : {-1e-3, 1e-4, 1e-3}) {
      // Along the bisector by s, off it by t toward b.
      const double px = mx - uy / len * s + ux / len * t, py = my + ux / len * s + uy / len * t;
      const double r = residual_at(px, py, a, b);
      EXPECT_NEAR(r, t, 10 * t * t + 1e-15) << s << " " << t;
    }
  }
}

TEST(BoundaryResidual, SmoothThroughEqualWeights) {
  // At k = 1 ± 1e-10 the Apollonius circle has radius ~1e10 and the closed form cancels
  // catastrophically; the residual must move by O(1e-10) only.
  const double a[3] = {0.0, 0.0, 0.0}, b[3] = {1.0, 0.0, 0.0};
  for (double py : {-0.7, 0.0, 0.4}) {
    for (double px : {0.45, 0.5, 0.52}) {
      const double equal = residual_at(px, py, a, b);
      for (double du : {-1e-10, 1e-10}) {
        const double a2[3] = {0.0, 0.0, du};
        EXPECT_NEAR(residual_at(px, py, a2, b), equal, 1e-9) << px << " " << py;
      }
    }
  }
}

TEST(BoundaryResidual, PositiveOnSiteBsSide) {
  // Brute force: positive exactly where p is weighted-closer to b.
  const double a[3] = {0.3, 0.1, std::log(1.7)}, b[3] = {0.8, 0.6, std::log(1.1)};
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      const double px = -1.0 + 0.075 * i + 0.001, py = -1.0 + 0.075 * j + 0.002;
      const double da = std::hypot(px - a[0], py - a[1]) / 1.7, db = std::hypot(px - b[0], py - b[1]) / 1.1;
      EXPECT_EQ(residual_at(px, py, a, b) > 0, da > db) << px << " " << py;
    }
  }
}

TEST(BoundaryResidual, FiniteWhereGradientVanishes) {
  // On the line through equal-weight sites, outside them, ∇f = 0: the floor keeps r finite and large.
  const double a[3] = {0.0, 0.0, 0.0}, b[3] = {1.0, 0.0, 0.0};
  const double r = residual_at(3.0, 0.0, a, b);
  EXPECT_TRUE(std::isfinite(r));
  EXPECT_GT(std::abs(r), 1e6);
}

TEST(BoundaryResidual, ScaleIsOneOverSigmaAndCommonWeightFactorCancels) {
  const double a[3] = {0.1, 0.2, 0.3}, b[3] = {0.9, 0.4, -0.2};
  const double shifted_a[3] = {0.1, 0.2, 0.3 + 5.0}, shifted_b[3] = {0.9, 0.4, -0.2 + 5.0};
  double r1 = 0.0, r4 = 0.0, shifted = 0.0;
  BoundaryResidual(0.6, 0.1, 1.0)(a, b, &r1);
  BoundaryResidual(0.6, 0.1, 4.0)(a, b, &r4);
  BoundaryResidual(0.6, 0.1, 1.0)(shifted_a, shifted_b, &shifted);
  EXPECT_DOUBLE_EQ(r4, 4.0 * r1);
  EXPECT_NEAR(shifted, r1, 1e-14);
}

}  // namespace
}  // namespace covmap::fitting
