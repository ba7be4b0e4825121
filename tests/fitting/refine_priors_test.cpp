// Priors and sites the samples do not (fully) determine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fit_test_data.h"
#include "fitting/refine.h"

namespace covmap::fitting {
namespace {

using testing::make_map;

constexpr double kNoise = 1e-3;

std::vector<BoundarySample> without_site(const std::vector<BoundarySample>& samples, int k, int keep) {
  std::vector<BoundarySample> out;
  for (const auto& s : samples) {
    if (s.site_a != k && s.site_b != k) {
      out.push_back(s);
    } else if (keep > 0) {
      out.push_back(s);
      --keep;
    }
  }
  return out;
}

TEST(Priors, SiteWithoutSamplesKeepsItsInitialValues) {
  const auto map = make_map(7, 3, 1.0, 2.0, 10);
  const int k = 4;
  const auto samples = without_site(map.samples, k, 0);
  auto start = map.sites;
  start[k].x += 0.3;  // a wrong start must stay where it is: nothing says otherwise
  const RefineResult result = refine_sites(start, samples);
  EXPECT_EQ(result.status[k], SiteStatus::kUnobserved);
  EXPECT_EQ(result.summary.sites_without_samples, 1u);
  EXPECT_EQ(result.sites[k].x, start[k].x);
  EXPECT_EQ(result.sites[k].y, start[k].y);
  EXPECT_FALSE(result.uncertainty[k].available);
  // Its weight keeps its ratio to the reference site (whose log weight is held).
  const int ref = result.uncertainty[0].log_weight_reference;
  ASSERT_NE(ref, kNone);
  EXPECT_NEAR(result.sites[k].weight / result.sites[ref].weight, start[k].weight / start[ref].weight, 1e-12);
  for (int i = 0; i < 7; ++i) {
    if (i != k) {
      EXPECT_EQ(result.status[i], SiteStatus::kRefined);
    }
  }
}

TEST(Priors, SiteWithoutSamplesTakesItsPriors) {
  const auto map = make_map(7, 3, 1.0, 2.0, 10);
  const int k = 4;
  const auto samples = without_site(map.samples, k, 0);
  // Two position priors combine by precision: (0.2/1 + 0.5/4) / (1 + 1/4) = 0.26 in x.
  const std::vector<SitePrior> priors = {{k, {0.2, 0.7}, 0.01, std::log(3.0), 0.1},
                                         {k, {0.5, 0.7}, 0.02, 0.0, 0.0}};
  const RefineResult result = refine_sites(map.sites, samples, priors);
  EXPECT_EQ(result.status[k], SiteStatus::kFromPrior);
  EXPECT_NEAR(result.sites[k].x, 0.26, 1e-12);
  EXPECT_NEAR(result.sites[k].y, 0.7, 1e-12);
  EXPECT_NEAR(result.uncertainty[k].sigma_x, 1 / std::sqrt(1 / 1e-4 + 1 / 4e-4), 1e-12);
  EXPECT_NEAR(result.uncertainty[k].sigma_log_weight, 0.1, 1e-12);
  EXPECT_TRUE(result.uncertainty[k].available);
  const int ref = result.uncertainty[0].log_weight_reference;
  EXPECT_NEAR(result.sites[k].weight / result.sites[ref].weight, 3.0 / map.sites[ref].weight, 1e-12);
}

TEST(Priors, PositionPriorPullsAnObservedSiteAsTheLinearGaussianUpdatePredicts) {
  // Oracle: for a linear-Gaussian model, adding an independent prior N(m, P) on a subset x of the
  // parameters moves x from the data estimate x_d (covariance C) to x_d + C (C + P)⁻¹ (m − x_d), and
  // its covariance to C − C (C + P)⁻¹ C. With σ = 1e-3 the model is linear to ~1e-3 relative.
  const auto map = make_map(7, 3, 1.0, 2.0, 6);
  std::mt19937_64 rng(17);
  const auto samples = testing::noisy(map.samples, rng, kNoise, kNoise);
  RefineOptions options;
  options.loss = RobustLoss::kNone;
  options.estimate_noise_scale = false;
  const int k = 2;
  const RefineResult data = refine_sites(map.sites, samples, {}, options);
  const auto& u = data.uncertainty[k];
  ASSERT_TRUE(u.available);
  const double c00 = u.sigma_x * u.sigma_x, c11 = u.sigma_y * u.sigma_y, c01 = u.cov_xy;
  // A prior as precise as the data, 3 data-σ away in x and −2 in y.
  const double p = std::sqrt(std::sqrt(c00 * c11));
  const double mx = data.sites[k].x + 3 * u.sigma_x, my = data.sites[k].y - 2 * u.sigma_y;
  const std::vector<SitePrior> priors = {{k, {mx, my}, p, 0.0, 0.0}};
  const RefineResult pulled = refine_sites(map.sites, samples, priors, options);

  // (C + P)⁻¹ for the 2×2 case.
  const double s00 = c00 + p * p, s11 = c11 + p * p, s01 = c01, det = s00 * s11 - s01 * s01;
  const double i00 = s11 / det, i11 = s00 / det, i01 = -s01 / det;
  const double dx = mx - data.sites[k].x, dy = my - data.sites[k].y;
  const double kx = i00 * dx + i01 * dy, ky = i01 * dx + i11 * dy;
  const double expect_x = data.sites[k].x + c00 * kx + c01 * ky;
  const double expect_y = data.sites[k].y + c01 * kx + c11 * ky;
  const double moved = std::hypot(expect_x - data.sites[k].x, expect_y - data.sites[k].y);
  EXPECT_NEAR(pulled.sites[k].x, expect_x, 0.02 * moved);
  EXPECT_NEAR(pulled.sites[k].y, expect_y, 0.02 * moved);
  // Posterior variance of x: C00 − (C (C+P)⁻¹ C)00.
  const double t0 = c00 * i00 + c01 * i01, t1 = c00 * i01 + c01 * i11;
  const double post_xx = c00 - (t0 * c00 + t1 * c01);
  EXPECT_NEAR(pulled.uncertainty[k].sigma_x, std::sqrt(post_xx), 0.02 * std::sqrt(post_xx));
}

TEST(Priors, SiteWithTwoSamplesIsUndeterminedUnlessAPriorFixesIt) {
  const auto map = make_map(7, 3, 1.0, 2.0, 10);
  std::mt19937_64 rng(23);
  const int k = 4;
  const auto samples = testing::noisy(without_site(map.samples, k, 2), rng, kNoise, kNoise);
  const RefineResult bare = refine_sites(map.sites, samples);
  EXPECT_EQ(bare.status[k], SiteStatus::kRefined);
  EXPECT_FALSE(bare.uncertainty[k].available);
  EXPECT_TRUE(std::isinf(bare.uncertainty[k].sigma_x));
  EXPECT_NE(bare.summary.message.find("undetermined"), std::string::npos) << bare.summary.message;
  for (int i = 0; i < 7; ++i) {
    if (i != k) {
      EXPECT_TRUE(bare.uncertainty[i].available) << "site " << i;
    }
  }

  const double prior_sigma = 0.01;
  const std::vector<SitePrior> priors = {
      {k, {map.sites[k].x + 0.005, map.sites[k].y}, prior_sigma, std::log(map.sites[k].weight), 0.05}};
  const RefineResult fixed = refine_sites(map.sites, samples, priors);
  ASSERT_TRUE(fixed.uncertainty[k].available) << fixed.summary.message;
  EXPECT_LE(fixed.uncertainty[k].sigma_x, prior_sigma * (1 + 1e-9));
  EXPECT_LE(fixed.uncertainty[k].sigma_y, prior_sigma * (1 + 1e-9));
  // Pulled toward the prior, within its σ of it.
  EXPECT_LT(std::hypot(fixed.sites[k].x - priors[0].position.x, fixed.sites[k].y - priors[0].position.y),
            3 * prior_sigma);
}

TEST(Priors, TwoSitesSeenOnlyThroughTheirBisectorAreUndetermined) {
  // One Apollonius circle fixes 3 numbers of the 5 free ones: each site alone (the other held) is
  // pinned, so only the joint (dense) diagnosis finds that neither is determined.
  const std::vector<Site> sites = {{"a", 0.0, 0.0, 1.5}, {"b", 1.0, 0.2, 1.0}};
  const auto samples = testing::boundary_samples(sites, 40);
  ASSERT_GT(samples.size(), 30u);
  const RefineResult result = refine_sites(sites, samples);
  EXPECT_FALSE(result.uncertainty[0].available);
  EXPECT_FALSE(result.uncertainty[1].available);
  EXPECT_NE(result.summary.message.find("2 site(s) undetermined"), std::string::npos) << result.summary.message;
  // The fit itself is fine: the samples lie on the bisector of the refined sites.
  EXPECT_LT(result.summary.rms_residual, 1e-9);
}

TEST(Priors, WeightPriorsFixTheScaleInsteadOfTheReferenceSite) {
  const auto map = make_map(6, 8, 1.0, 2.0, 10);
  std::mt19937_64 rng(29);
  const auto samples = testing::noisy(map.samples, rng, kNoise, kNoise);
  const std::vector<SitePrior> priors = {{1, {}, 0.0, std::log(map.sites[1].weight), 0.2}};
  const RefineResult result = refine_sites(map.sites, samples, priors);
  for (std::size_t i = 0; i < map.sites.size(); ++i) {
    EXPECT_EQ(result.uncertainty[i].log_weight_reference, kNone);
    // Absolute log weights: every one carries (about) the prior's σ, none is exactly 0.
    EXPECT_GT(result.uncertainty[i].sigma_log_weight, 0.19);
    EXPECT_LT(result.uncertainty[i].sigma_log_weight, 0.21);
  }
}

}  // namespace
}  // namespace covmap::fitting
