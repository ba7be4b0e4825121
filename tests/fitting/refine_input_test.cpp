// Malformed input is rejected with a message naming the item; options validate; names round-trip.
#include <ceres/types.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include "fitting/refine.h"

namespace covmap::fitting {
namespace {

const std::vector<Site> kSites = {{"a", 0, 0, 1}, {"b", 1, 0, 1}, {"c", 0, 1, 2}};
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The message of the invalid_argument refine_sites throws ("" if it does not throw).
std::string rejection(std::vector<Site> sites, std::vector<BoundarySample> samples,
                      std::vector<SitePrior> priors = {}, RefineOptions options = {}) {
  try {
    refine_sites(sites, samples, priors, options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(RefineInput, SampleProblemsAreNamed) {
  EXPECT_TRUE(contains(rejection(kSites, {{{0.5, 0.1}, 0, 3}}), "samples[0] (chain 0): site_b 3 out of range"));
  EXPECT_TRUE(contains(rejection(kSites, {{{0.5, 0.1}, -1, 1}}), "site_a -1 out of range"));
  EXPECT_TRUE(contains(rejection(kSites, {{{0.5, 0.1}, 1, 1, 1.0, 7}}), "samples[0] (chain 7): site_a and site_b"));
  EXPECT_TRUE(contains(rejection(kSites, {{{kNaN, 0.1}, 0, 1}}), "point must be finite"));
  EXPECT_TRUE(contains(rejection(kSites, {{{0.5, 0.1}, 0, 1, 0.0}}), "sigma must be finite and positive"));
  EXPECT_TRUE(contains(rejection(kSites, {{{1.0, 0.0}, 0, 1}}), "point is exactly at site 1"));
  auto twins = kSites;
  twins[1].x = 0;
  EXPECT_TRUE(contains(rejection(twins, {{{0.5, 0.5}, 0, 1}}), "sites 0 and 1 start at the same position"));
}

TEST(RefineInput, SiteAndPriorProblemsAreNamed) {
  auto sites = kSites;
  sites[2].weight = -1;
  EXPECT_TRUE(contains(rejection(sites, {}), "initial[2] (site 'c'): weight must be finite and positive"));
  sites = kSites;
  sites[0].x = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(contains(rejection(sites, {}), "initial[0] (site 'a'): position must be finite"));
  EXPECT_TRUE(contains(rejection({}, {}), "no sites"));
  EXPECT_TRUE(contains(rejection(kSites, {}, {{5, {}, 1.0}}), "priors[0]: site 5 out of range"));
  EXPECT_TRUE(contains(rejection(kSites, {}, {{0, {}, kNaN}}), "priors[0]: position_sigma must be finite"));
  EXPECT_TRUE(contains(rejection(kSites, {}, {{0, {kNaN, 0}, 1.0}}), "priors[0]: position must be finite"));
  EXPECT_TRUE(contains(rejection(kSites, {}, {{0, {}, 0.0, kNaN, 0.5}}), "log_weight must be finite"));
  // Switched-off parts of a prior may hold anything.
  EXPECT_EQ(rejection(kSites, {}, {{0, {kNaN, kNaN}, 0.0, kNaN, -1.0}}), "");
}

TEST(RefineInput, AllProblemsAreReportedTogether) {
  const std::string message = rejection(kSites, {{{0.5, 0.1}, 0, 9}, {{0.5, 0.1}, 2, 2}, {{0.5, 0.1}, 0, 1, -2.0}});
  EXPECT_TRUE(contains(message, "3 problems")) << message;
  EXPECT_TRUE(contains(message, "samples[0]"));
  EXPECT_TRUE(contains(message, "samples[1]"));
  EXPECT_TRUE(contains(message, "samples[2]"));
}

TEST(RefineInput, OptionsAreValidated) {
  std::string error;
  EXPECT_TRUE(RefineOptions{}.IsValid(&error));
  RefineOptions options;
  options.loss_scale = 0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_TRUE(contains(error, "loss_scale"));
  EXPECT_TRUE(contains(rejection(kSites, {}, {}, options), "invalid options: loss_scale"));
  options = {};
  options.max_iterations = 0;
  EXPECT_FALSE(options.IsValid(nullptr));
  options = {};
  options.threads = 0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_TRUE(contains(error, "threads"));
}

TEST(RefineInput, NamesRoundTrip) {
  for (RobustLoss loss : {RobustLoss::kNone, RobustLoss::kHuber, RobustLoss::kCauchy}) {
    RobustLoss parsed = loss == RobustLoss::kNone ? RobustLoss::kCauchy : RobustLoss::kNone;
    ASSERT_TRUE(from_string(to_string(loss), &parsed));
    EXPECT_EQ(parsed, loss);
  }
  RobustLoss untouched = RobustLoss::kHuber;
  EXPECT_FALSE(from_string("Cauchy ", &untouched));
  EXPECT_EQ(untouched, RobustLoss::kHuber);
  EXPECT_EQ(to_string(SiteStatus::kFromPrior), "from-prior");
}

TEST(RefineInput, TerminationNamesRoundTrip) {
  std::set<std::string> names;
  for (Termination termination : kAllTerminations) {
    Termination parsed = termination == Termination::kSettled ? Termination::kNotRun : Termination::kSettled;
    ASSERT_TRUE(from_string(to_string(termination), &parsed)) << to_string(termination);
    EXPECT_EQ(parsed, termination);
    names.insert(to_string(termination));
  }
  EXPECT_EQ(names.size(), kAllTerminations.size());
  // Reports carry Ceres' own names.
  for (ceres::TerminationType type :
       {ceres::CONVERGENCE, ceres::NO_CONVERGENCE, ceres::FAILURE, ceres::USER_SUCCESS, ceres::USER_FAILURE}) {
    Termination parsed = Termination::kNotRun;
    EXPECT_TRUE(from_string(ceres::TerminationTypeToString(type), &parsed)) << ceres::TerminationTypeToString(type);
  }
  EXPECT_EQ(to_string(Termination::kNotRun), "");
  Termination untouched = Termination::kSettled;
  EXPECT_FALSE(from_string("convergence", &untouched));
  EXPECT_EQ(untouched, Termination::kSettled);
}

TEST(RefineInput, NoSamplesIsANormalResult) {
  const RefineResult result = refine_sites(kSites, {});
  EXPECT_EQ(result.summary.termination, Termination::kNoSamples);
  EXPECT_EQ(to_string(result.summary.termination), "NO_SAMPLES");
  EXPECT_EQ(result.summary.sites_without_samples, 3u);
  ASSERT_EQ(result.sites.size(), 3u);
  EXPECT_EQ(result.sites[2].weight, 1.0);
  EXPECT_EQ(result.sites[0].weight, 0.5);
  EXPECT_FALSE(result.summary.brief().empty());
}

}  // namespace
}  // namespace covmap::fitting
