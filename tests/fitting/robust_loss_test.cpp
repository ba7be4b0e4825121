// The noise statistics of fitting/robust_loss.h against independent computations.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "fitting/robust_loss.h"

namespace covmap::fitting::detail {
namespace {

std::vector<double> gaussian(std::size_t n, double sd, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, sd);
  std::vector<double> r(n);
  for (double& ri : r) ri = normal(rng);
  return r;
}

TEST(VarianceFactor, LeastSquaresIsReducedChiSquare) {
  const std::vector<double> r = {0.5, -1.5, 2.0, 0.1, -0.7};
  const VarianceFactor k = estimate_variance_factor(RobustLoss::kNone, 1.0, r, 2);
  ASSERT_TRUE(k.ok);
  EXPECT_NEAR(k.value, (0.25 + 2.25 + 4.0 + 0.01 + 0.49) / 3, 1e-15);
  EXPECT_FALSE(estimate_variance_factor(RobustLoss::kNone, 1.0, r, 5).ok);
  EXPECT_EQ(model_variance_factor(RobustLoss::kNone, 1.0), 1.0);
}

TEST(VarianceFactor, ModelFactorAgreesWithMonteCarlo) {
  // E[w] E[ψ²] / E[ψ']² under r ~ N(0, 1), by sampling, with the Cauchy derivatives written out
  // here: ρ(s) = c² log(1 + s/c²), w = 1/(1 + r²/c²), ψ = r w, ψ' = w − 2 (r²/c²) w².
  const auto r = gaussian(400000, 1.0, 3);
  for (double c : {0.5, 1.0, 2.0}) {
    double w = 0, psi2 = 0, dpsi = 0;
    for (double ri : r) {
      const double q = ri * ri / (c * c), wi = 1 / (1 + q);
      w += wi;
      psi2 += ri * ri * wi * wi;
      dpsi += wi - 2 * q * wi * wi;
    }
    const double n = static_cast<double>(r.size());
    const double expected = (w / n) * (psi2 / n) / ((dpsi / n) * (dpsi / n));
    EXPECT_NEAR(model_variance_factor(RobustLoss::kCauchy, c), expected, 0.01 * expected) << c;
  }
  // Huber at a scale far beyond the residuals is least squares.
  EXPECT_NEAR(model_variance_factor(RobustLoss::kHuber, 50.0), 1.0, 1e-12);
}

TEST(RobustScale, GaussianResidualsGiveTheirStandardDeviation) {
  EXPECT_NEAR(robust_noise_scale(gaussian(100000, 3.0, 4), 0), 3.0, 0.03);
  EXPECT_NEAR(robust_noise_scale(gaussian(100000, 1e-6, 5), 0), 1e-6, 1e-8);
  EXPECT_EQ(robust_noise_scale(std::vector<double>(10, 0.0), 2), 0.0);
}

TEST(RobustScale, FivePercentGrossOutliersMoveItLittle) {
  auto r = gaussian(20000, 1.0, 6);
  double sum_squares = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i % 20 == 0) r[i] = 30.0;
    sum_squares += r[i] * r[i];
  }
  EXPECT_GT(std::sqrt(sum_squares / r.size()), 6.0);  // the RMS is ruined
  EXPECT_LT(robust_noise_scale(r, 0), 1.1);
  EXPECT_GT(robust_noise_scale(r, 0), 0.95);
}

TEST(VarianceFactor, NominalSigmaFarFromTheNoiseScalesBySquare) {
  // Residuals 10× larger than σ says: κ ≈ 100 · V(c/10) for every loss; 100 for plain least
  // squares and for a loss whose scale is far beyond the residuals.
  const auto r = gaussian(100000, 10.0, 7);
  EXPECT_NEAR(estimate_variance_factor(RobustLoss::kNone, 1.0, r, 10).value, 100.0, 2.0);
  EXPECT_NEAR(estimate_variance_factor(RobustLoss::kHuber, 1000.0, r, 10).value, 100.0, 3.0);
  const double cauchy = estimate_variance_factor(RobustLoss::kCauchy, 10.0, r, 10).value;
  EXPECT_NEAR(cauchy, 100.0 * model_variance_factor(RobustLoss::kCauchy, 1.0), 3.0);
}

}  // namespace
}  // namespace covmap::fitting::detail
