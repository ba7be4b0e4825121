// The engine on nearly degenerate input, against the independent checker (check/). Exactly
// degenerate sets (collinear, cocircular, grid, equal weights) are perturbed by one ulp and by
// 1e-15, 1e-12 and 1e-9 relative, at coordinates up to 1e7: every decision the doubles imply must
// be taken exactly and every node placed on its curves. The engine constructs nodes from the
// sites alone (engine/triple_node.h): nodes built otherwise put arc ends of 20 sites on y = x/2
// moved by an ulp up to 800 units off their own curves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "check/check.h"
#include "site_families.h"
#include "voronoi/engine.h"

namespace covmap::voronoi {
namespace {

using testing::NearBase;
using testing::Perturbation;

struct NearCase {
  NearBase base;
  Perturbation perturbation;
};

class EngineNearDegenerate : public ::testing::TestWithParam<NearCase> {};

TEST_P(EngineNearDegenerate, CheckerFindsNoViolation) {
  const NearCase c = GetParam();
  check::CheckOptions options;
  options.boundary_probes = 400;
  options.samples_per_arc = 8;
  options.max_reported = 100000;
  int seed = 0;
  for (const double extent : {100.0, 1e4, 1e7})
    for (int k = 0; k < 8; ++k) {
      ++seed;
      const auto sites = testing::make_near_degenerate(c.base, c.perturbation, 40, extent, seed);
      const Diagram d = build_diagram(sites);
      const check::CheckReport report = check::check_diagram(d, options);
      ASSERT_TRUE(report.ok()) << testing::near_base_name(c.base) << " "
                               << testing::perturbation_name(c.perturbation) << " extent " << extent
                               << " seed " << seed << ": " << report.brief();
    }
}

std::vector<NearCase> all_cases() {
  std::vector<NearCase> cases;
  for (NearBase b : {NearBase::Collinear, NearBase::Cocircular, NearBase::Grid, NearBase::EqualWeight})
    for (Perturbation p : {Perturbation::Ulp, Perturbation::Rel1e15, Perturbation::Rel1e12, Perturbation::Rel1e9})
      cases.push_back({b, p});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Families, EngineNearDegenerate, ::testing::ValuesIn(all_cases()),
                         [](const auto& info) {
                           return std::string(testing::near_base_name(info.param.base)) + "_" +
                                  testing::perturbation_name(info.param.perturbation);
                         });

}  // namespace
}  // namespace covmap::voronoi
