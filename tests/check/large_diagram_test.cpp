// The checker must handle 10^5-site diagrams in well under a minute.
#include <gtest/gtest.h>

#include "../check/check_test_util.h"
#include "../check/hand_diagrams.h"

namespace covmap::check::testing {
namespace {

TEST(LargeDiagram, LatticeOfHundredThousandSites) {
  const Diagram d = lattice(317);  // 100489 sites, 200344 arcs, 99856 nodes
  const CheckReport r = check_diagram(d);
  EXPECT_TRUE(is_ok(r));
  EXPECT_EQ(r.nodes_checked, d.nodes.size());
  EXPECT_LT(r.seconds, 30.0) << r.brief();
  std::printf("%s\n", r.brief().c_str());
}

TEST(LargeDiagram, OneWrongSideAmongHundredThousand) {
  Diagram d = lattice(317);
  std::swap(d.arcs[12345].left_site, d.arcs[12345].right_site);
  const CheckReport r = check_diagram(d);
  ASSERT_EQ(r.total_violations(), 1u) << r.brief();
  EXPECT_EQ(r.violations[0].kind, ViolationKind::ArcSidesSwapped);
  EXPECT_EQ(r.violations[0].arc, 12345);
}

}  // namespace
}  // namespace covmap::check::testing
