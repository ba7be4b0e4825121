// audit::judge against closed forms computed here: the Mahalanobis distance² of a reported sensor
// from its reconstruction (2×2 with and without correlation, a third independent log-weight
// component, floors and stated sigmas added in quadrature), its degrees of freedom, the 2-dof
// threshold as the quantile of the 3-dof threshold's tail probability, and the decision at the
// threshold itself.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "audit/verdict.h"

namespace covmap::audit {
namespace {

// The χ² tails in closed form: Q₂(t) = e^{−t/2}, Q₃(t) = erfc(√(t/2)) + √(2t/π) e^{−t/2}.
double tail2(double t) { return std::exp(-0.5 * t); }
double tail3(double t) { return std::erfc(std::sqrt(0.5 * t)) + std::sqrt(2.0 * t / M_PI) * std::exp(-0.5 * t); }

// Q₃ by quadrature of the χ²₃ density √x e^{−x/2} / √(2π) (substituting x = u², so the integrand
// 2u² e^{−u²/2} / √(2π) is smooth at 0), composite Simpson: grounds the closed form above.
double tail3_by_quadrature(double t) {
  const int n = 20000;  // even
  const double b = std::sqrt(t), h = b / n;
  auto f = [](double u) { return 2.0 * u * u * std::exp(-0.5 * u * u) / std::sqrt(2.0 * M_PI); };
  double sum = f(0.0) + f(b);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * f(k * h);
  return 1.0 - sum * h / 3.0;
}

// The 2-dof threshold of the same tail probability as the 3-dof threshold t3: Q₂(t2) = Q₃(t3).
double threshold2_of(double t3) { return -2.0 * std::log(tail3(t3)); }

// Published quantiles (any χ² table): the 95 % and 99 % points of χ²₂ and χ²₃.
constexpr double kChi2_3_95 = 7.814727903251178;
constexpr double kChi2_2_95 = 5.991464547107979;  // = 2 ln 20
constexpr double kChi2_3_99 = 11.344866730144373;
constexpr double kChi2_2_99 = 9.210340371976184;  // = 2 ln 100

// A large threshold: the χ² value is what is tested, not the decision.
constexpr double kLoose = 1e6;

VerdictInput position_only(double dx, double dy, double var_x, double var_y, double cov_xy) {
  VerdictInput in;
  in.dx = dx, in.dy = dy, in.var_x = var_x, in.var_y = var_y, in.cov_xy = cov_xy;
  return in;
}

// dᵀ C⁻¹ d for the symmetric 2×2 C = [[a, c], [c, b]], by the explicit inverse.
double mahalanobis2(double dx, double dy, double a, double b, double c) {
  return (b * dx * dx - 2.0 * c * dx * dy + a * dy * dy) / (a * b - c * c);
}

TEST(Verdict, TheTailClosedFormsMatchQuadratureAndTables) {
  for (double t : {0.5, 2.0, kChi2_3_95, kChi2_3_99, 20.0})
    EXPECT_NEAR(tail3(t), tail3_by_quadrature(t), 1e-12) << t;
  EXPECT_NEAR(tail3(kChi2_3_95), 0.05, 1e-12);
  EXPECT_NEAR(tail3(kChi2_3_99), 0.01, 1e-12);
  EXPECT_NEAR(tail2(kChi2_2_95), 0.05, 1e-15);
  EXPECT_NEAR(threshold2_of(kChi2_3_95), kChi2_2_95, 1e-9);
  EXPECT_NEAR(threshold2_of(kChi2_3_99), kChi2_2_99, 1e-9);
}

TEST(Verdict, DiagonalPositionCovariance) {
  // (2, 3) against variances 4 and 9: χ² = 2²/4 + 3²/9 = 2, two degrees of freedom.
  const Judgement j = judge(position_only(2.0, 3.0, 4.0, 9.0, 0.0), kLoose);
  EXPECT_DOUBLE_EQ(j.chi2, 2.0);
  EXPECT_EQ(j.dof, 2);
  EXPECT_FALSE(j.inconsistent);
  // The sign of the difference does not matter.
  EXPECT_DOUBLE_EQ(judge(position_only(-2.0, 3.0, 4.0, 9.0, 0.0), kLoose).chi2, 2.0);
}

TEST(Verdict, CorrelatedPositionCovariance) {
  // C = [[5, 2], [2, 3]], d = (1, -2): χ² = (3·1 + 2·2·2 + 5·4) / (15 − 4) = 31/11.
  EXPECT_NEAR(judge(position_only(1.0, -2.0, 5.0, 3.0, 2.0), kLoose).chi2, 31.0 / 11.0, 1e-14);
  // Along the correlation the same distance costs less than across it.
  const double along = judge(position_only(1.0, 1.0, 5.0, 5.0, 4.0), kLoose).chi2;
  const double across = judge(position_only(1.0, -1.0, 5.0, 5.0, 4.0), kLoose).chi2;
  EXPECT_NEAR(along, 2.0 / 9.0, 1e-14);   // 1ᵀC⁻¹1 with eigenvalue 9 along (1, 1)
  EXPECT_NEAR(across, 2.0 / 1.0, 1e-14);  // eigenvalue 1 along (1, −1)
  // A spread of general cases against the explicit inverse.
  for (double c : {-2.9, -1.0, 0.0, 0.7, 2.5})
    for (double dx : {-3.0, 0.5, 4.0}) {
      const double a = 4.0, b = 2.5, dy = 1.5;
      EXPECT_NEAR(judge(position_only(dx, dy, a, b, c), kLoose).chi2, mahalanobis2(dx, dy, a, b, c),
                  1e-12 * mahalanobis2(dx, dy, a, b, c))
          << "c=" << c << " dx=" << dx;
    }
}

TEST(Verdict, StatedSigmaAndFloorAddInQuadratureToBothAxes) {
  // Reconstruction variances 1 and 4, correlation 1; stated σ 2 m and a 3 m floor add 4 + 9 = 13
  // to each axis (not to the covariance): C = [[14, 1], [1, 17]].
  VerdictInput in = position_only(3.0, -4.0, 1.0, 4.0, 1.0);
  in.reported_position_sigma = 2.0;
  in.position_floor = 3.0;
  EXPECT_NEAR(judge(in, kLoose).chi2, mahalanobis2(3.0, -4.0, 14.0, 17.0, 1.0), 1e-14);
  // Quadrature, not a sum of sigmas: σ 2 + floor 3 is not (2 + 3)² = 25 per axis.
  EXPECT_GT(std::abs(judge(in, kLoose).chi2 - mahalanobis2(3.0, -4.0, 26.0, 29.0, 1.0)), 0.1);
  // A floor alone, no reconstruction variance: χ² = |d|² / floor².
  VerdictInput floor_only = position_only(3.0, 4.0, 0.0, 0.0, 0.0);
  floor_only.position_floor = 5.0;
  EXPECT_NEAR(judge(floor_only, kLoose).chi2, 1.0, 1e-15);
}

TEST(Verdict, WeightDifferenceIsAThirdIndependentComponent) {
  // Position part as in CorrelatedPositionCovariance (31/11); log weight: variance 0.01 + stated
  // 0.2² + floor 0.1² = 0.06, difference 0.3: 0.09 / 0.06 = 1.5.
  VerdictInput in = position_only(1.0, -2.0, 5.0, 3.0, 2.0);
  in.dlogw = 0.3;
  in.var_logw = 0.01;
  in.reported_logw_sigma = 0.2;
  in.logw_floor = 0.1;
  const Judgement j = judge(in, kLoose);
  EXPECT_EQ(j.dof, 3);
  EXPECT_NEAR(j.chi2, 31.0 / 11.0 + 1.5, 1e-13);
  // No stated log-weight σ: only the reconstruction's variance and the floor (0.02).
  in.reported_logw_sigma.reset();
  EXPECT_NEAR(judge(in, kLoose).chi2, 31.0 / 11.0 + 0.09 / 0.02, 1e-12);
  // A zero weight difference still counts as a degree of freedom, and adds nothing.
  in.dlogw = 0.0;
  EXPECT_EQ(judge(in, kLoose).dof, 3);
  EXPECT_NEAR(judge(in, kLoose).chi2, 31.0 / 11.0, 1e-14);
}

TEST(Verdict, WithoutAReportedWeightTheLogWeightTermsAreIgnored) {
  VerdictInput in = position_only(2.0, 3.0, 4.0, 9.0, 0.0);
  in.var_logw = 1e-6;  // would dominate if it were used
  in.reported_logw_sigma = 1e-3;
  in.logw_floor = 1e-3;
  const Judgement j = judge(in, kLoose);
  EXPECT_EQ(j.dof, 2);
  EXPECT_DOUBLE_EQ(j.chi2, 2.0);
}

TEST(Verdict, DecisionFlipsExactlyAtTheThreeDofThreshold) {
  // Unit covariance, d = (3, 0, 0): χ² = 9 exactly in floating point.
  VerdictInput in = position_only(3.0, 0.0, 1.0, 1.0, 0.0);
  in.dlogw = 0.0;
  in.var_logw = 1.0;
  ASSERT_EQ(judge(in, 9.0).chi2, 9.0);
  EXPECT_FALSE(judge(in, 9.0).inconsistent) << "χ² equal to the threshold is consistent";
  EXPECT_TRUE(judge(in, std::nextafter(9.0, 0.0)).inconsistent);
  EXPECT_FALSE(judge(in, std::nextafter(9.0, 10.0)).inconsistent);
  // At the tabled 95 % point: just inside and just outside.
  const double r = std::sqrt(kChi2_3_95);
  in.dx = r * (1.0 - 1e-9);
  EXPECT_FALSE(judge(in, kChi2_3_95).inconsistent);
  in.dx = r * (1.0 + 1e-9);
  EXPECT_TRUE(judge(in, kChi2_3_95).inconsistent);
}

TEST(Verdict, TwoDofThresholdIsTheQuantileOfTheSameTailProbability) {
  // Without a weight the threshold for 7.8147 (95 % with 3 dof) is 5.9915 (95 % with 2 dof), not
  // 7.8147: a position that is 6.5 σ² off is inconsistent with 2 dof but would pass with 3.
  for (auto [t3, t2] : {std::pair{kChi2_3_95, kChi2_2_95}, std::pair{kChi2_3_99, kChi2_2_99}}) {
    const double r = std::sqrt(t2);
    EXPECT_FALSE(judge(position_only(r * (1.0 - 1e-7), 0.0, 1.0, 1.0, 0.0), t3).inconsistent) << t3;
    EXPECT_TRUE(judge(position_only(r * (1.0 + 1e-7), 0.0, 1.0, 1.0, 0.0), t3).inconsistent) << t3;
  }
  // Other thresholds: the quantile from the closed forms of both tails.
  for (double t3 : {1.0, 4.0, 16.0, 30.0}) {
    const double t2 = threshold2_of(t3);
    EXPECT_NEAR(tail2(t2), tail3(t3), 1e-14 + 1e-10 * tail3(t3));
    const double r = std::sqrt(t2);
    EXPECT_FALSE(judge(position_only(0.0, r * (1.0 - 1e-7), 1.0, 1.0, 0.0), t3).inconsistent) << t3;
    EXPECT_TRUE(judge(position_only(0.0, r * (1.0 + 1e-7), 1.0, 1.0, 0.0), t3).inconsistent) << t3;
  }
}

TEST(Verdict, NaNIsJudgedInconsistent) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(judge(position_only(nan, 0.0, 1.0, 1.0, 0.0), kLoose).inconsistent);
  VerdictInput in = position_only(0.0, 0.0, 1.0, 1.0, 0.0);
  in.dlogw = nan;
  in.var_logw = 1.0;
  const Judgement j = judge(in, kLoose);
  EXPECT_TRUE(j.inconsistent);
  EXPECT_EQ(j.reason.rfind("inconsistent", 0), 0u) << j.reason;
}

// Found while writing these tests: a NaN in the covariance (the reconstruction's var_x, or var_logw)
// was judged consistent, whatever the difference: the LDLT solve yields a finite χ² (the NaN pivot
// does not propagate), so the NaN guard (!(χ² <= threshold)) never saw it. An unknown uncertainty
// must not pass. (NaN differences: see NaNIsJudgedInconsistent.)
TEST(Verdict, NaNCovarianceIsJudgedInconsistent) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(judge(position_only(0.0, 0.0, nan, 1.0, 0.0), kLoose).inconsistent);
  EXPECT_TRUE(judge(position_only(0.0, 1.0, nan, 1.0, 0.0), kLoose).inconsistent);
  EXPECT_TRUE(judge(position_only(1.0, 1.0, nan, 1.0, 0.0), kLoose).inconsistent);
  VerdictInput in = position_only(1.0, 1.0, 1.0, 1.0, 0.0);
  in.dlogw = 0.0;
  in.var_logw = nan;
  EXPECT_TRUE(judge(in, kLoose).inconsistent);
}

TEST(Verdict, ReasonStatesTheDecision) {
  const Judgement ok = judge(position_only(1.0, 0.0, 1.0, 1.0, 0.0), 9.0);
  EXPECT_EQ(ok.reason.rfind("consistent", 0), 0u) << ok.reason;
  const Judgement bad = judge(position_only(10.0, 0.0, 1.0, 1.0, 0.0), 9.0);
  EXPECT_EQ(bad.reason.rfind("inconsistent", 0), 0u) << bad.reason;
  EXPECT_NE(bad.reason.find("2 degrees of freedom"), std::string::npos) << bad.reason;
}

}  // namespace
}  // namespace covmap::audit
