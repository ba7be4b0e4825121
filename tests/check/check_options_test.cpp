// Options validation, kind names and report summaries.
#include <gtest/gtest.h>

#include "../check/hand_diagrams.h"
#include "check/check.h"

namespace covmap::check {
namespace {

TEST(CheckOptions, DefaultsAreValid) {
  std::string why;
  EXPECT_TRUE(CheckOptions{}.is_valid(&why)) << why;
}

TEST(CheckOptions, RejectsBadFieldsByName) {
  std::string why;
  CheckOptions o;
  o.samples_per_arc = 0;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("samples_per_arc"), std::string::npos);
  o = {};
  o.bisection_tolerance = o.relative_tolerance;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("bisection_tolerance"), std::string::npos);
  o = {};
  o.relative_tolerance = -1;
  EXPECT_FALSE(o.is_valid(nullptr));
  EXPECT_THROW(check_diagram(Diagram{}, o), std::invalid_argument);
}

TEST(ViolationKind, NamesRoundTrip) {
  for (std::size_t k = 0; k < kViolationKindCount; ++k) {
    const auto kind = static_cast<ViolationKind>(k);
    ViolationKind back = ViolationKind::ArcsCross;
    ASSERT_TRUE(violation_kind_from_string(to_string(kind), &back));
    EXPECT_EQ(back, kind);
  }
  ViolationKind untouched = ViolationKind::BadSite;
  EXPECT_FALSE(violation_kind_from_string("NoSuchKind", &untouched));
  EXPECT_EQ(untouched, ViolationKind::BadSite);
}

TEST(CheckReport, BriefNamesKindsAndFirstViolation) {
  Diagram d = testing::triangle();
  d.nodes[0].x += 0.5;
  const CheckReport r = check_diagram(d);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.brief().find("NodeNotEquidistant"), std::string::npos) << r.brief();
  EXPECT_EQ(check_diagram(testing::triangle()).brief().rfind("OK", 0), 0u);
}

TEST(CheckReport, AMissingRayIsReportedWhereItShouldBe) {
  // The square's fourth ray (from (1, 1) towards -x, between the sites at (0, 0) and (0, 2)) is
  // removed: every violation must point at that ray or its node, the half-line y = 1, x <= 1.
  Diagram d = testing::square();
  d.arcs.pop_back();
  const CheckReport r = check_diagram(d);
  ASSERT_FALSE(r.ok());
  for (const Violation& v : r.violations) {
    EXPECT_NEAR(v.y, 1.0, 0.05) << to_string(v.kind) << " at (" << v.x << ", " << v.y << "): " << v.message;
    EXPECT_LE(v.x, 1.05) << to_string(v.kind) << " at (" << v.x << ", " << v.y << "): " << v.message;
  }
}

TEST(DiagramScale, DiagonalOfValidSitesOrOne) {
  Diagram d = testing::triangle();  // (0,0) (4,0) (1,3): box 4 x 3
  EXPECT_DOUBLE_EQ(diagram_scale(d), 5.0);
  d.sites[1].weight = -1;  // left out: box 1 x 3
  EXPECT_DOUBLE_EQ(diagram_scale(d), std::sqrt(10.0));
  EXPECT_DOUBLE_EQ(diagram_scale(Diagram{}), 1.0);
}

TEST(CheckDiagram, EmptyAndSingleSiteAreFine) {
  EXPECT_TRUE(check_diagram(Diagram{}).ok());
  Diagram one;
  one.sites = {testing::site(3, 4)};
  EXPECT_TRUE(check_diagram(one).ok());
}

}  // namespace
}  // namespace covmap::check
