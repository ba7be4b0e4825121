// recognize() compares the sites a graph carries with its reconstruction (input_sites.h): the
// engine's own labelled diagram agrees; two labels swapped, a site moved or reweighted, and a label
// taken off each disagree, naming the site and the amount. The oracle is the ground truth of the
// change made to the engine's output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "recognition/recognize.h"
#include "voronoi/engine.h"

namespace covmap::recognition {
namespace {

Diagram labelled(int seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), w(1.0, 2.0);
  std::vector<Site> sites;
  for (int i = 0; i < 40; ++i) sites.push_back({"s" + std::to_string(i), u(rng), u(rng), w(rng)});
  return voronoi::build_diagram(sites);
}

const SiteDifference* find_kind(const InputSitesComparison& c, SiteDifferenceKind kind) {
  for (const auto& d : c.differences)
    if (d.kind == kind) return &d;
  return nullptr;
}

TEST(InputSites, TheEngineLabelsAgree) {
  for (int seed = 1; seed <= 5; ++seed) {
    const Reconstruction r = recognize(labelled(seed));
    ASSERT_TRUE(r.bisector_graph) << r.reason;
    ASSERT_TRUE(r.input_sites.has_value());
    EXPECT_TRUE(r.input_sites->agree) << r.input_sites->differences.front().message;
    EXPECT_TRUE(r.input_sites->positions_compared);
  }
}

TEST(InputSites, NoSitesNoComparison) {
  Diagram d = labelled(1);
  d.sites.clear();
  for (Arc& a : d.arcs) a.left_site = a.right_site = kNone;
  EXPECT_FALSE(recognize(d).input_sites.has_value());
}

TEST(InputSites, SwappedLabelsAreNamed) {
  Diagram d = labelled(2);
  std::swap(d.sites[3].x, d.sites[7].x);
  std::swap(d.sites[3].y, d.sites[7].y);
  std::swap(d.sites[3].weight, d.sites[7].weight);
  const Reconstruction r = recognize(d);
  ASSERT_TRUE(r.input_sites.has_value());
  EXPECT_FALSE(r.input_sites->agree);
  const SiteDifference* swapped = find_kind(*r.input_sites, SiteDifferenceKind::kSwappedLabel);
  ASSERT_NE(swapped, nullptr);
  EXPECT_TRUE(swapped->input_site == 3 || swapped->input_site == 7) << swapped->message;
  EXPECT_NEAR(swapped->amount, std::hypot(d.sites[3].x - d.sites[7].x, d.sites[3].y - d.sites[7].y), 1e-9);
  EXPECT_GT(swapped->relative, 1.0);
}

// Cocircular sites (radius 50) with equal weights, each coordinate perturbed by a relative 1e-9:
// the nodes crowd within ~1e-7 of the centre while the sites lie 50 away, so the graph fixes them
// only to the nodes' rounding magnified by that ratio (the reconstruction was 1.4e-6 off the
// drawing sites, "2.6e6 tolerances" of the graph's tiny extent, and the engine's own labels were
// said to disagree). A site d away from the graph is compared at τ·d more; a swapped label (a
// chord of the circle off) is still named.
TEST(InputSites, SitesFarFromTheirCrowdedNodesAgreeAtTheirConditioning) {
  int compared = 0;
  for (int seed = 1; seed <= 5; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> angle(0.0, 2 * M_PI), sign(-1.0, 1.0);
    std::vector<Site> sites;
    for (int i = 0; i < 16; ++i) {
      const double a = angle(rng);
      const double x = 1 + 50 * std::cos(a), y = 1 + 50 * std::sin(a);
      sites.push_back({"s" + std::to_string(i), x * (1 + (sign(rng) > 0 ? 1e-9 : -1e-9)),
                       y * (1 + (sign(rng) > 0 ? 1e-9 : -1e-9)), 1.0});
    }
    Diagram d = voronoi::build_diagram(sites);
    const Reconstruction r = recognize(d);
    ASSERT_TRUE(r.bisector_graph) << "seed " << seed << ": " << r.reason;
    ASSERT_TRUE(r.input_sites.has_value());
    EXPECT_TRUE(r.input_sites->agree) << "seed " << seed << ": " << r.input_sites->differences.front().message;
    if (!r.input_sites->positions_compared) continue;
    ++compared;
    std::swap(d.sites[3].x, d.sites[7].x);
    std::swap(d.sites[3].y, d.sites[7].y);
    const Reconstruction swapped = recognize(d);
    ASSERT_TRUE(swapped.input_sites.has_value());
    EXPECT_FALSE(swapped.input_sites->agree) << "seed " << seed;
  }
  EXPECT_GE(compared, 1);  // the case that disagreed: a unique reconstruction, positions compared
}

TEST(InputSites, MovedAndReweightedSitesAreNamedWithTheirAmounts) {
  {
    Diagram d = labelled(3);
    d.sites[5].x += 1e-4;  // 1e-4 of a unit square: ~700 tolerances of 1e-7 times its diagonal
    const Reconstruction r = recognize(d);
    ASSERT_TRUE(r.input_sites.has_value());
    EXPECT_FALSE(r.input_sites->agree);
    ASSERT_EQ(r.input_sites->differences.size(), 1u) << r.input_sites->differences.front().message;
    const SiteDifference& moved = r.input_sites->differences.front();
    EXPECT_EQ(moved.kind, SiteDifferenceKind::kPosition);
    EXPECT_EQ(moved.input_site, 5);
    EXPECT_NEAR(moved.amount, 1e-4, 1e-9);
  }
  {
    Diagram d = labelled(4);
    d.sites[9].weight *= 1.001;
    const Reconstruction r = recognize(d);
    ASSERT_TRUE(r.input_sites.has_value());
    EXPECT_FALSE(r.input_sites->agree);
    ASSERT_EQ(r.input_sites->differences.size(), 1u) << r.input_sites->differences.front().message;
    const SiteDifference& reweighted = r.input_sites->differences.front();
    EXPECT_EQ(reweighted.kind, SiteDifferenceKind::kWeight);
    EXPECT_EQ(reweighted.input_site, 9);
    EXPECT_NEAR(reweighted.amount, 1e-3, 1e-8);
  }
}

TEST(InputSites, ConflictingAndMissingLabelsAreNamed) {
  {
    Diagram d = labelled(5);
    // One arc names the wrong site on its left: that site now names the faces of two sites.
    Arc& a = d.arcs[4];
    const int wrong = a.left_site == 0 ? 1 : 0;
    a.left_site = wrong == a.right_site ? 2 : wrong;
    const Reconstruction r = recognize(d);
    ASSERT_TRUE(r.input_sites.has_value());
    EXPECT_FALSE(r.input_sites->agree);
    EXPECT_NE(find_kind(*r.input_sites, SiteDifferenceKind::kConflictingLabel), nullptr);
  }
  {
    Diagram d = labelled(6);
    d.arcs[2].right_site = kNone;
    const Reconstruction r = recognize(d);
    ASSERT_TRUE(r.input_sites.has_value());
    EXPECT_FALSE(r.input_sites->agree);
    const SiteDifference* missing = find_kind(*r.input_sites, SiteDifferenceKind::kMissingLabel);
    ASSERT_NE(missing, nullptr);
    EXPECT_EQ(missing->arc, 2);
  }
}

}  // namespace
}  // namespace covmap::recognition
