// The path-loss exponent from the map and the reported powers: closed forms on synthetic lines,
// and generated maps whose truth (the generator's alpha) the estimate must contain.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "audit/alpha_estimate.h"
#include "generated_map_audit.h"

namespace covmap::audit {
namespace {

// A map sensor of weight w (largest = 1 is not needed: the common factor is free) reported at P.
SensorAudit sensor(double weight, double power_dbm) {
  SensorAudit s;
  s.weight = weight;
  ReportedSensor r;
  r.tx_power_dbm = power_dbm;
  s.reported = r;
  return s;
}

double power_of(double weight, double alpha) { return 43.0 + 10.0 * alpha * std::log10(weight); }

TEST(AlphaEstimate, AnExactLineGivesItsAlpha) {
  std::vector<SensorAudit> sensors;
  for (int i = 0; i < 12; ++i) {
    const double w = std::pow(10.0, -i / 10.0);
    sensors.push_back(sensor(w * 0.37, power_of(w, 2.7)));  // any common factor
  }
  const auto e = estimate_alpha(sensors, 2.7);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->low, 2.7, 1e-9);
  EXPECT_NEAR(e->high, 2.7, 1e-9);
  EXPECT_EQ(e->sensors, 12u);
  EXPECT_EQ(e->outliers, 0u);
  EXPECT_FALSE(e->disagrees);
  EXPECT_TRUE(estimate_alpha(sensors, 27.0)->disagrees);
  // 3 % off is within what powers are reported to, even on an exact map.
  EXPECT_FALSE(estimate_alpha(sensors, 2.7 * 1.03)->disagrees);
}

TEST(AlphaEstimate, NoisyPowersWithGrossErrorsContainTheTruth) {
  std::mt19937_64 random(5);
  std::normal_distribution<double> noise(0.0, 1.0);  // dB
  std::uniform_real_distribution<double> log_w(std::log(0.25), 0.0);
  int contained = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<SensorAudit> sensors;
    for (int i = 0; i < 60; ++i) {
      const double w = std::exp(log_w(random));
      double p = power_of(w, 3.5) + noise(random);
      if (i % 10 == 0) p += 8.0;  // a gross power error
      sensors.push_back(sensor(w, p));
    }
    const auto e = estimate_alpha(sensors, std::nullopt);
    ASSERT_TRUE(e);
    EXPECT_GE(e->outliers, 5u) << trial;  // the six gross errors, give or take one within the noise
    EXPECT_LT(e->sigma_low, 0.5);
    contained += 3.5 >= e->low - 3 * e->sigma_low && 3.5 <= e->high + 3 * e->sigma_high;
    EXPECT_LT(e->high, 1.2 * e->low);  // 1 dB of noise on 10 dB of spread: a narrow bracket
  }
  EXPECT_GE(contained, 38);  // 3 σ holds but for the odd trial
}

TEST(AlphaEstimate, UndeterminedWithoutSpreadOrWithoutPoints) {
  std::vector<SensorAudit> same_power;
  for (int i = 0; i < 10; ++i) same_power.push_back(sensor(1.0 - 0.01 * i, 40.0 + 0.1 * (i % 2)));
  EXPECT_FALSE(estimate_alpha(same_power, 3.5));
  std::vector<SensorAudit> few = {sensor(1, 43), sensor(0.5, 33), sensor(0.25, 22)};
  EXPECT_FALSE(estimate_alpha(few, 3.5));
  std::vector<SensorAudit> backwards;  // stronger powers on weaker cells: no alpha explains them
  for (int i = 0; i < 10; ++i) backwards.push_back(sensor(std::pow(0.8, i), 30.0 + 2.0 * i));
  EXPECT_FALSE(estimate_alpha(backwards, 3.5));
  std::vector<SensorAudit> unreported;
  for (int i = 0; i < 10; ++i) {
    SensorAudit s = sensor(std::pow(0.8, i), power_of(std::pow(0.8, i), 3.5));
    if (i % 2) s.in_map = false;
    else s.reported->tx_power_dbm.reset();
    unreported.push_back(s);
  }
  EXPECT_FALSE(estimate_alpha(unreported, 3.5));
}

// Generated maps (the generator's alpha is 3.5): the audit's interval contains it, whatever alpha
// the user typed, and a typo is named.
TEST(AlphaEstimate, GeneratedMapsContainTheGeneratorsAlphaAndNameATypo) {
  const std::vector<Site> sites = testing::sensors(60, 21);
  for (const double typed : {3.5, 35.0}) {
    const testing::AuditRun r = testing::run(testing::base_options(21), sites, typed);
    ASSERT_TRUE(r.result.alpha_estimate) << typed;
    const AlphaEstimate& e = *r.result.alpha_estimate;
    EXPECT_GE(3.5, e.low - 3 * e.sigma_low) << e.low << " ± " << e.sigma_low;
    EXPECT_LE(3.5, e.high + 3 * e.sigma_high) << e.high << " ± " << e.sigma_high;
    EXPECT_EQ(e.disagrees, typed == 35.0);
  }
}

}  // namespace
}  // namespace covmap::audit
