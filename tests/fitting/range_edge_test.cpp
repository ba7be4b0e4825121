// Range edges in refine_sites: a sample with site_b = kNone lies on the circle of radius
// R·w about its site, one R for the map. Oracles: the true sites and R the samples were drawn from
// (closed forms: range circles about the sites, the Apollonius circle of two weighted sites).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "fitting/local_uncertainty.h"
#include "fitting/refine.h"

namespace covmap::fitting {
namespace {

// Points of the range circle of site `i` (radius range·w) at angles in [from, to], each moved
// radially by noise.
void add_range_arc(std::vector<BoundarySample>& out, const std::vector<Site>& sites, int i, double range, double from,
                   double to, int count, double noise, std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, noise);
  const double r = range * sites[i].weight;
  for (int k = 0; k < count; ++k) {
    const double t = from + (to - from) * (k + 0.5) / count;
    const double rr = r + (noise > 0 ? n(rng) : 0.0);
    out.push_back({{sites[i].x + rr * std::cos(t), sites[i].y + rr * std::sin(t)}, i, kNone, 1.0, 0});
  }
}

// Points of the Apollonius circle of sites a and b (weights differ), at angles in [from, to].
void add_bisector_arc(std::vector<BoundarySample>& out, const std::vector<Site>& sites, int a, int b, double from,
                      double to, int count) {
  const double k = sites[a].weight / sites[b].weight;
  const double cx = (sites[a].x - k * k * sites[b].x) / (1 - k * k), cy = (sites[a].y - k * k * sites[b].y) / (1 - k * k);
  const double radius = k * std::hypot(sites[a].x - sites[b].x, sites[a].y - sites[b].y) / std::abs(1 - k * k);
  for (int j = 0; j < count; ++j) {
    const double t = from + (to - from) * (j + 0.5) / count;
    out.push_back({{cx + radius * std::cos(t), cy + radius * std::sin(t)}, a, b, 1.0, 1});
  }
}

// Two neighbours whose bisector is a circle about the lighter one, each with a range edge on its
// far side, and a third sensor alone in its disc (no boundary with anyone: only R ties its weight
// to the others').
struct Scene {
  std::vector<Site> truth{{"a", 0.0, 0.0, 1.0}, {"b", 3.0, 0.5, 0.7}, {"c", 20.0, -4.0, 0.55}};
  double range = 4.0;  // R for weight 1
  std::vector<BoundarySample> samples;
  explicit Scene(double noise) {
    std::mt19937 rng(7);
    // The a|b Apollonius circle surrounds b (the lighter); its part within both reaches.
    add_bisector_arc(samples, truth, 0, 1, 2.2, 4.1, 40);
    add_range_arc(samples, truth, 0, range, 1.5, 4.8, 80, noise, rng);
    add_range_arc(samples, truth, 1, range, -1.2, 1.3, 60, noise, rng);
    add_range_arc(samples, truth, 2, range, 0.0, 2.0 * M_PI, 100, noise, rng);
  }
};

std::vector<Site> perturbed(std::vector<Site> sites) {
  for (std::size_t i = 0; i < sites.size(); ++i) {
    sites[i].x += 0.3 * std::cos(1.0 + i), sites[i].y += 0.3 * std::sin(2.0 + i);
    sites[i].weight *= 1.0 + 0.15 * (i % 2 ? 1 : -1);
  }
  return sites;
}

TEST(RangeEdges, ExactSamplesGiveSitesWeightsAndRange) {
  const Scene scene(0.0);
  RefineOptions options;
  options.loss = RobustLoss::kNone;
  const RefineResult got = refine_sites(perturbed(scene.truth), scene.samples, {}, options);
  ASSERT_TRUE(got.range.has_value());
  // The truth's largest weight is 1, so R comes back as it was drawn.
  EXPECT_NEAR(*got.range, scene.range, 1e-7 * scene.range);
  for (std::size_t i = 0; i < scene.truth.size(); ++i) {
    EXPECT_NEAR(got.sites[i].x, scene.truth[i].x, 1e-7) << i;
    EXPECT_NEAR(got.sites[i].y, scene.truth[i].y, 1e-7) << i;
    // c shares no boundary with a or b: its weight relative to theirs comes through R alone.
    EXPECT_NEAR(got.sites[i].weight, scene.truth[i].weight, 1e-7) << i;
    EXPECT_EQ(got.status[i], SiteStatus::kRefined) << i;
  }
  for (double r : got.sample_residual) EXPECT_NEAR(r, 0.0, 1e-7);
}

TEST(RangeEdges, WeightScaleNormalisationCarriesTheRange) {
  // Every weight halved and R doubled: the same reaches R·w. The refined weights are normalised
  // (largest 1), so R must come back as the reach of the strongest site, and every R·w unchanged.
  Scene scene(0.0);
  for (Site& s : scene.truth) s.weight *= 0.5;
  scene.range *= 2.0;
  const RefineResult got = refine_sites(perturbed(scene.truth), scene.samples);
  ASSERT_TRUE(got.range.has_value());
  EXPECT_NEAR(*got.range, 0.5 * scene.range, 1e-6 * scene.range);
  for (std::size_t i = 0; i < scene.truth.size(); ++i)
    EXPECT_NEAR(*got.range * got.sites[i].weight, scene.range * scene.truth[i].weight, 1e-6) << i;
}

TEST(RangeEdges, NoisySamplesStayWithinTheirUncertainty) {
  const Scene scene(0.02);
  const RefineResult got = refine_sites(perturbed(scene.truth), scene.samples);
  ASSERT_TRUE(got.range.has_value());
  EXPECT_GT(got.range_sigma, 0.0);
  EXPECT_LT(std::abs(*got.range - scene.range), 4.0 * got.range_sigma + 1e-9);
  const std::vector<LocalUncertainty> local = local_uncertainty(got.sites, scene.samples, 1.0, got.range);
  for (std::size_t i = 0; i < scene.truth.size(); ++i) {
    ASSERT_TRUE(local[i].available) << i;
    EXPECT_LT(std::abs(got.sites[i].x - scene.truth[i].x), 5.0 * local[i].sigma_x + 1e-3) << i;
    EXPECT_LT(std::abs(got.sites[i].y - scene.truth[i].y), 5.0 * local[i].sigma_y + 1e-3) << i;
  }
  // The isolated disc is determined by its range edge alone.
  EXPECT_LT(local[2].sigma_x, 0.01);
  // R's spread between the three sites: their range arcs carry independent noise 0.02 over 60–100
  // samples each, so each implies R to ~0.02 / w / √60 ≈ 3e-3..5e-3, and the spread of three is of
  // that order; the truth lies within a few of it.
  const double spread = range_sigma(got.sites, scene.samples);
  EXPECT_GT(spread, 1e-4);
  EXPECT_LT(spread, 3e-2);
  EXPECT_LT(std::abs(*got.range - scene.range), 5.0 * spread);
}

TEST(RangeEdges, WithoutRangeTheIsolatedSensorIsUnobserved) {
  // The oracle of the test above, negated: without range samples nothing ties c to the map.
  Scene scene(0.0);
  std::erase_if(scene.samples, [](const BoundarySample& s) { return s.site_b == kNone; });
  const RefineResult got = refine_sites(perturbed(scene.truth), scene.samples);
  EXPECT_FALSE(got.range.has_value());
  EXPECT_EQ(got.status[2], SiteStatus::kUnobserved);
}

TEST(RangeEdges, LocalUncertaintyNeedsTheRange) {
  const Scene scene(0.01);
  EXPECT_THROW(local_uncertainty(scene.truth, scene.samples, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace covmap::fitting
