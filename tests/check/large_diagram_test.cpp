// The checker must handle 10^5-site diagrams in well under a minute.
#include <gtest/gtest.h>

#include "../check/check_test_util.h"
#include "../check/hand_diagrams.h"

namespace covmap::check::testing {
namespace {

// The bound is the release build's. Under AddressSanitizer (scripts/sanitize.sh) the checker is
// several times slower, more so among the whole suite on a loaded machine, so there it gets four
// times as long.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kSecondsBound = 120.0;
#else
constexpr double kSecondsBound = 30.0;
#endif

TEST(LargeDiagram, LatticeOfHundredThousandSites) {
  const Diagram d = lattice(317);  // 100489 sites, 200344 arcs, 99856 nodes
  const CheckReport r = check_diagram(d);
  EXPECT_TRUE(is_ok(r));
  EXPECT_EQ(r.nodes_checked, d.nodes.size());
  EXPECT_LT(r.seconds, kSecondsBound) << r.brief();
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
