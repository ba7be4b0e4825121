// The MWVD is scale invariant: scaling the positions scales the diagram, and scaling the weights
// changes nothing. The engine must be too, on every magnitude a double can hold, up to inputs of
// 1e308: it scales its input by powers of two, without which sites 1e9 apart give a diagram the
// checker rejects and sites 1e15 apart give infinite nodes.
#include <gtest/gtest.h>

#include <cmath>

#include "check/check.h"
#include "site_families.h"
#include "voronoi/engine.h"

namespace covmap::voronoi {
namespace {

using testing::Family;

std::vector<Site> scaled(std::vector<Site> sites, double position_scale, double weight_scale) {
  for (Site& s : sites) {
    s.x *= position_scale;
    s.y *= position_scale;
    s.weight *= weight_scale;
  }
  return sites;
}

const Family kFamilies[] = {Family::UniformWeights, Family::EqualWeights, Family::WeightClasses, Family::Grid};

// Oracle: the diagram of the unscaled sites. A power-of-two scale is exact in doubles, so the
// scaled input is exactly the scaled problem: the same nodes in the same order, each exactly the
// scaled reference node.
TEST(EngineScale, PowerOfTwoScalesGiveExactlyTheScaledDiagram) {
  for (const Family family : kFamilies) {
    const auto base = testing::make_sites(family, 25, 7);
    const Diagram reference = build_diagram(base);
    for (const int e : {-1000, -40, -10, 10, 30, 50, 330, 960}) {
      const Diagram d = build_diagram(scaled(base, std::ldexp(1.0, e), 1.0));
      ASSERT_EQ(d.nodes.size(), reference.nodes.size()) << testing::family_name(family) << " 2^" << e;
      ASSERT_EQ(d.arcs.size(), reference.arcs.size()) << testing::family_name(family) << " 2^" << e;
      for (std::size_t k = 0; k < d.nodes.size(); ++k) {
        EXPECT_EQ(d.nodes[k].x, std::ldexp(reference.nodes[k].x, e)) << testing::family_name(family) << " 2^" << e;
        EXPECT_EQ(d.nodes[k].y, std::ldexp(reference.nodes[k].y, e)) << testing::family_name(family) << " 2^" << e;
      }
    }
  }
}

// Oracle: the independent checker, at decimal scales (not exact, so rounding may break a
// degeneracy differently; the diagram must still be the MWVD of what it was given). The checker
// squares distances, so its own range ends near 1e±150; the exact test above covers the rest.
TEST(EngineScale, EveryMagnitudePassesTheChecker) {
  for (const Family family : kFamilies) {
    const auto base = testing::make_sites(family, 25, 7);
    for (const double scale : {1e-100, 1e-12, 1e-3, 1e3, 1e9, 1e12, 1e15, 1e100}) {
      const Diagram d = build_diagram(scaled(base, scale, 1.0));
      check::CheckOptions options;
      options.boundary_probes = 300;
      const check::CheckReport report = check::check_diagram(d, options);
      EXPECT_TRUE(report.ok()) << testing::family_name(family) << " scale " << scale << ": " << report.brief();
    }
  }
}

TEST(EngineScale, WeightsOnlyCountAsRatios) {
  const auto base = testing::make_sites(Family::UniformWeights, 25, 11);
  const Diagram reference = build_diagram(base);
  for (const int e : {-600, -60, 60, 600}) {
    const double w = std::ldexp(1.0, e);
    const Diagram d = build_diagram(scaled(base, 1.0, w));
    ASSERT_EQ(d.nodes.size(), reference.nodes.size()) << w;
    for (std::size_t k = 0; k < d.nodes.size(); ++k) {
      EXPECT_EQ(d.nodes[k].x, reference.nodes[k].x) << w;
      EXPECT_EQ(d.nodes[k].y, reference.nodes[k].y) << w;
    }
  }
}

// Sites whose values cannot be scaled together exactly are refused by name, not built wrongly.
TEST(EngineScale, MagnitudesBeyondOneDoubleRangeAreRefused) {
  const std::vector<Site> sites = {{"big", 1e300, 0, 1}, {"tiny", 1e-300, 0, 1}, {"c", 0, 1e300, 2}};
  try {
    build_diagram(sites);
    FAIL() << "accepted sites spanning 600 orders of magnitude";
  } catch (const InvalidSites& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].id, "tiny");
  }
}

}  // namespace
}  // namespace covmap::voronoi
