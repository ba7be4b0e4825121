// The engine against the independent checker (check/), on random instances of every input
// family. The checker shares no code with the engine: it tests the MWVD definition directly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "site_families.h"
#include "check/check.h"
#include "voronoi/engine.h"

namespace covmap::voronoi {
namespace {

using testing::Family;

struct Case {
  Family family;
  int n;
  int seeds;
};

class EngineChecked : public ::testing::TestWithParam<Case> {};

TEST_P(EngineChecked, CheckerFindsNoViolation) {
  const Case c = GetParam();
  check::CheckOptions options;
  options.boundary_probes = 600;
  options.samples_per_arc = 8;
  for (int seed = 1; seed <= c.seeds; ++seed) {
    const auto sites = testing::make_sites(c.family, c.n, seed);
    const Diagram d = build_diagram(sites);
    const check::CheckReport report = check::check_diagram(d, options);
    ASSERT_TRUE(report.ok()) << testing::family_name(c.family) << " n=" << sites.size()
                             << " seed=" << seed << ": " << report.brief();
    if (sites.size() >= 3 && c.family != Family::Collinear) {
      EXPECT_FALSE(d.arcs.empty());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Families, EngineChecked,
    ::testing::Values(Case{Family::UniformWeights, 3, 60}, Case{Family::UniformWeights, 12, 150},
                      Case{Family::UniformWeights, 150, 40}, Case{Family::EqualWeights, 3, 40},
                      Case{Family::EqualWeights, 60, 40}, Case{Family::WeightClasses, 40, 60},
                      Case{Family::SharedMaximum, 40, 60}, Case{Family::Grid, 30, 60},
                      Case{Family::Collinear, 12, 40}, Case{Family::LargeCoordinates, 60, 40}),
    [](const auto& info) {
      return std::string(testing::family_name(info.param.family)) + "_n" +
             std::to_string(info.param.n);
    });

TEST(EngineSpecialCases, OneSiteHasNoArcs) {
  const std::vector<Site> one = {{"a", 1, 2, 3}};
  const Diagram d = build_diagram(one);
  EXPECT_TRUE(d.arcs.empty());
  EXPECT_TRUE(d.nodes.empty());
}

TEST(EngineSpecialCases, TwoSitesGiveTheApolloniusCircle) {
  // Closed form: sites (0,0) w=1 and (3,0) w=2: |p|/1 = |p-(3,0)|/2 → centre (-1,0), radius 2.
  const std::vector<Site> two = {{"a", 0, 0, 1}, {"b", 3, 0, 2}};
  const Diagram d = build_diagram(two);
  ASSERT_EQ(d.arcs.size(), 1u);
  const Arc& arc = d.arcs[0];
  ASSERT_TRUE(std::holds_alternative<Circle>(arc.curve));
  const Circle c = std::get<Circle>(arc.curve);
  EXPECT_NEAR(c.cx, -1.0, 1e-12);
  EXPECT_NEAR(c.cy, 0.0, 1e-12);
  EXPECT_NEAR(c.r, 2.0, 1e-12);
  EXPECT_EQ(arc.from, kNone);
  EXPECT_EQ(arc.to, kNone);
}

TEST(EngineSpecialCases, SquareGivesOneNodeOfDegreeFour) {
  // Four equal weights on a square with weight 3 (lifted coordinates not representable in double):
  // exactly one node, at the centre, with four rays.
  const std::vector<Site> square = {
      {"a", 0, 0, 3}, {"b", 1, 0, 3}, {"c", 1, 1, 3}, {"d", 0, 1, 3}};
  const Diagram d = build_diagram(square);
  ASSERT_EQ(d.nodes.size(), 1u);
  EXPECT_NEAR(d.nodes[0].x, 0.5, 1e-15);
  EXPECT_NEAR(d.nodes[0].y, 0.5, 1e-15);
  EXPECT_EQ(d.arcs.size(), 4u);
  for (const Arc& a : d.arcs) EXPECT_TRUE(a.from == 0 || a.to == 0);
}

TEST(EngineSpecialCases, CocircularWeightedSitesMeetInOneNode) {
  // Sites at distance w from the origin are all weighted-equidistant (1) from it: a node of degree
  // five. Coordinates are exact (Pythagorean), so the degeneracy is exact too.
  const std::vector<Site> sites = {{"a", 1, 0, 1}, {"b", 0, 2, 2},  {"c", -3, 0, 3},
                                   {"d", 0, -4, 4}, {"e", 3, 4, 5}};
  const Diagram d = build_diagram(sites);
  int at_origin = 0;
  for (const Node& n : d.nodes)
    if (std::hypot(n.x, n.y) < 1e-9) ++at_origin;
  EXPECT_EQ(at_origin, 1) << "the five-fold point must be one node, not several close ones";
  int arcs_at_origin = 0;
  for (const Arc& a : d.arcs)
    for (int end : {a.from, a.to})
      if (end != kNone && std::hypot(d.nodes[end].x, d.nodes[end].y) < 1e-9) ++arcs_at_origin;
  EXPECT_GE(arcs_at_origin, 3);
  const check::CheckReport report = check::check_diagram(d);
  EXPECT_TRUE(report.ok()) << report.brief();
}

TEST(EngineSpecialCases, NodeAtTheEndOfAHalfEdgeToInfinityIsFinite) {
  // Three equal weights around (4, 1) and a half weight at distance 1 from it, then rounded as
  // recognition's reconstructed sites are: the degree-four node splits, and one of its nodes is the
  // very start of a half-edge whose other end is at infinity. That end is a root of the crossing
  // equation too; the crossing itself, rounded to -0 or to just below 0, lost to it and the node
  // came out as 0/0 = NaN (found by scripts/sanitize.sh: recognition's compare hashed the NaN).
  const std::vector<std::vector<Site>> inputs = {
      {{"a", 2, 1, 1}, {"b", 6, 1, 1}, {"c", 4, 3, 1}, {"d", 5, 1.0000000000000004, 0.5}},
      {{"a", 1.9999999999999982, 0.99999999999999911, 1},
       {"b", 6.0000000000000018, 0.99999999999999911, 1},
       {"c", 4.0000000000000009, 3.0000000000000004, 1},
       {"d", 5, 1.0000000000000004, 0.49999999999999939}}};
  for (const auto& sites : inputs) {
    const Diagram d = build_diagram(sites);
    int near_centre = 0;
    for (const Node& n : d.nodes) {
      EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y)) << n.x << ", " << n.y;
      if (std::hypot(n.x - 4, n.y - 1) < 1e-9) ++near_centre;
    }
    EXPECT_GE(near_centre, 2) << "both nodes of the split degree-four node";
    const check::CheckReport report = check::check_diagram(d);
    EXPECT_TRUE(report.ok()) << report.brief();
  }
}

// Sites an ulp off a grid (k/9, weights 1 and 2) as recognition reconstructs them from the engine's
// own diagram of the grid: a short circle arc between nodes an ulp apart, not mended itself, had both
// ends merged by other arcs' mends into nodes whose coordinates give one angle around its centre,
// and the self-check refused the diagram ("an arc's distinct end nodes round to one point").
TEST(EngineSpecialCases, ShortArcBetweenMergedClustersIsMergedToo) {
  const std::vector<Site> sites = {
      {"s0", 0.2222222222222222, -1.5183021000533443e-17, 1.0},
      {"s1", 0.3333333333333333, 0.11111111111111109, 0.49999999999999983},
      {"s2", 1.3307893377268299e-17, -1.082670044798068e-17, 1.0},
      {"s3", 0.1111111111111111, 0.1111111111111111, 1.0},
      {"s4", 0.4444444444444444, 0.22222222222222224, 1.0},
      {"s5", 0.7777777777777778, 0.5555555555555556, 1.0},
      {"s6", 0.4444444444444444, 0.11111111111111109, 1.0},
      {"s7", 0.7777777777777778, 0.11111111111111112, 0.49999999999999983},
      {"s8", 0.1111111111111111, 0.6666666666666666, 0.49999999999999983},
      {"s9", 0.3333333333333333, 0.7777777777777778, 1.0},
      {"s10", 0.2222222222222222, 0.5555555555555556, 0.49999999999999983},
      {"s11", 0.22222222222222215, 0.8888888888888888, 0.49999999999999983},
      {"s12", 0.11111111111111113, 0.22222222222222227, 1.0},
      {"s13", 0.22222222222222218, 0.22222222222222224, 1.0},
      {"s14", 0.4444444444444444, -5.139396461010636e-18, 1.0},
      {"s15", 0.4444444444444444, 0.6666666666666666, 0.49999999999999983},
      {"s16", 0.4444444444444444, 0.8888888888888888, 1.0},
      {"s17", 0.3333333333333333, 0.8888888888888888, 1.0},
      {"s18", 0.4444444444444444, 0.7777777777777778, 0.49999999999999983},
      {"s19", 0.1111111111111111, 0.4444444444444444, 0.49999999999999983},
      {"s20", 0.7777777777777778, 0.3333333333333333, 0.49999999999999983},
      {"s21", 0.3333333333333333, 0.4444444444444444, 0.49999999999999983},
      {"s22", 0.8888888888888888, 0.6666666666666666, 0.49999999999999983},
      {"s23", 0.7777777777777778, 0.6666666666666666, 0.49999999999999983},
      {"s24", 0.6666666666666667, -6.919650491177369e-18, 0.49999999999999983},
      {"s25", 0.6666666666666666, 0.3333333333333333, 0.49999999999999983},
      {"s26", 0.5555555555555556, -3.2006749233317816e-18, 0.49999999999999983},
      {"s27", 0.6666666666666666, 0.22222222222222224, 0.49999999999999983},
      {"s28", 0.5555555555555556, 0.11111111111111112, 0.49999999999999983}};
  Diagram d;
  ASSERT_NO_THROW(d = build_diagram(sites));
  const check::CheckReport report = check::check_diagram(d);
  EXPECT_TRUE(report.ok()) << report.brief();
}

TEST(EngineInput, InvalidSitesAreAllNamed) {
  const double nan = std::nan("");
  const std::vector<Site> bad = {{"ok", 0, 0, 1},   {"neg", 1, 0, -2}, {"nan", nan, 0, 1},
                                 {"dup", 0, 0, 2},  {"zero", 3, 3, 0}, {"inf", 4, 4, INFINITY}};
  try {
    build_diagram(bad);
    FAIL() << "expected InvalidSites";
  } catch (const InvalidSites& e) {
    std::vector<int> indices;
    for (const auto& p : e.problems()) indices.push_back(p.index);
    EXPECT_EQ(indices, (std::vector<int>{1, 2, 3, 4, 5}));
    EXPECT_NE(std::string(e.what()).find("'dup'"), std::string::npos);
  }
}

// Large inputs are validated beside the triangulation (build_diagram.cpp, BesideTriangulation):
// they must be refused exactly as find_invalid_sites refuses them, whatever the triangulation of
// the invalid sites does meanwhile (duplicates, sites closer than the supported separation, a
// weight beyond the supported ratio, a coordinate that cannot even be scaled exactly).
TEST(EngineInput, LargeInvalidInputsAreRefusedAsTheValidationFindsThem) {
  const auto base = testing::make_sites(testing::Family::UniformWeights, 30000, 7);
  std::vector<std::vector<Site>> cases(5, base);
  cases[0][100].x = cases[0][5].x, cases[0][100].y = cases[0][5].y;  // duplicate position
  cases[1][9].x = 0, cases[1][9].y = 0, cases[1][200].x = 1e-300, cases[1][200].y = 0;  // too close
  cases[2][300].weight = 1e-20;     // weight ratio beyond 2^40
  cases[3][400].x = 5e-324;         // cannot be scaled with the others
  cases[4][500].x = 1e20;           // too far from the others
  for (std::size_t k = 0; k < cases.size(); ++k) {
    std::vector<InvalidSite> expected = find_invalid_sites(cases[k]);
    // A denormal coordinate is in range; it is refused by the scaling, which names it.
    if (k == 3) expected = {{400, cases[k][400].id, ""}};
    ASSERT_FALSE(expected.empty()) << "case " << k;
    try {
      build_diagram(cases[k]);
      FAIL() << "case " << k << ": expected InvalidSites";
    } catch (const InvalidSites& e) {
      ASSERT_EQ(e.problems().size(), expected.size()) << "case " << k;
      for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(e.problems()[i].index, expected[i].index) << "case " << k;
        if (k != 3) EXPECT_EQ(e.problems()[i].problem, expected[i].problem) << "case " << k;
      }
    }
  }
}

}  // namespace
}  // namespace covmap::voronoi

namespace covmap::voronoi {
namespace {

// Large enough for the engine's parallel extraction (engine/parallel.h): a bug in how workers
// share the edges would drop or duplicate arcs, breaking the faces and the checker.
TEST(EngineLarge, ParallelExtractionIsComplete) {
  const auto sites = testing::make_sites(testing::Family::UniformWeights, 30000, 99);
  const Diagram d = build_diagram(sites);
  std::vector<int> own(sites.size(), 0);
  for (const Face& f : d.faces)
    if (!f.orphan) ++own[f.site];
  for (std::size_t s = 0; s < sites.size(); ++s) ASSERT_EQ(own[s], 1) << "site " << s;
  // No arc twice: each (site pair, end nodes) is unique.
  std::vector<std::tuple<int, int, int, int>> keys;
  for (const Arc& a : d.arcs) keys.emplace_back(a.left_site, a.right_site, a.from, a.to);
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());
  check::CheckOptions options;
  options.boundary_probes = 3000;
  options.samples_per_arc = 3;
  const check::CheckReport report = check::check_diagram(d, options);
  EXPECT_TRUE(report.ok()) << report.brief();
}

}  // namespace
}  // namespace covmap::voronoi
