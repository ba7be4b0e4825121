// Each hand-built diagram, corrupted one way, must be reported with the right kind at the right
// place. Expected places come from the construction, never from the checker.
#include <gtest/gtest.h>

#include "../check/check_test_util.h"
#include "../check/hand_diagrams.h"

namespace covmap::check::testing {
namespace {

TEST(CorruptedDiagrams, MovedNodeIsNotEquidistant) {
  Diagram d = triangle();
  d.nodes[0] = Node{2.1, 1.0};
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::NodeNotEquidistant);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->node, 0);
  EXPECT_TRUE(near(*v, 2.1, 1.0, 1e-12));
  // The rays still pass through (2,1), so the moved node is off the vertical one.
  EXPECT_GT(r.count(ViolationKind::ArcEndNotOnCurve), 0u);
}

TEST(CorruptedDiagrams, WeightedNodeMovedAlongItsCircle) {
  // Sliding N1 along the A|B circle keeps it on that arc's curve but off the A|C circle.
  Diagram d = weighted_lens();
  const double a = std::atan2(d.nodes[0].y, d.nodes[0].x + 4.0 / 3) + 0.01;
  d.nodes[0] = Node{-4.0 / 3 + 8.0 / 3 * std::cos(a), 8.0 / 3 * std::sin(a)};
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::NodeNotEquidistant);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->node, 0);
}

TEST(CorruptedDiagrams, SwappedSidesOfLine) {
  Diagram d = triangle();
  std::swap(d.arcs[2].left_site, d.arcs[2].right_site);
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcSidesSwapped);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 2);
  // The sample is on the ray from (2,1) along (1,1).
  EXPECT_NEAR(v->x - 2.0, v->y - 1.0, 1e-9);
  EXPECT_GT(v->x, 2.0);
  // Nothing else is wrong: the pair of sites is still the right one.
  EXPECT_EQ(r.total_violations(), 1u) << r.brief();
}

TEST(CorruptedDiagrams, ReversedCircleSwapsSides) {
  // Clockwise travel puts the outside (B) on the left, but the arc still names A on the left.
  Diagram d = two_weighted_sites();
  d.arcs[0].ccw = false;
  clear_faces(d);
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcSidesSwapped);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 0);
  EXPECT_NEAR(std::hypot(v->x + 1, v->y), 2.0, 1e-9);  // on the circle
  EXPECT_EQ(r.total_violations(), 1u) << r.brief();
}

TEST(CorruptedDiagrams, WrongArcOfRightCircle) {
  // The B|C arc taken the other way round its circle: A is closer along it, and the true B|C
  // boundary is left uncovered. Right circle, right ends, so nothing structural is wrong.
  const Diagram d = weighted_theta(/*use_wrong_arc=*/true);
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcSiteCloser);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 2);
  EXPECT_EQ(v->site, 0);
  EXPECT_GT(r.count(ViolationKind::BoundaryNotCovered), 0u);
  EXPECT_EQ(r.count(ViolationKind::ArcNotOnBisector) + r.count(ViolationKind::ArcEndNotOnCurve) +
                r.count(ViolationKind::NodeNotEquidistant) + r.count(ViolationKind::ArcsCross),
            0u)
      << r.brief();
}

TEST(CorruptedDiagrams, ShiftedCircleRadius) {
  Diagram d = two_weighted_sites();
  std::get<Circle>(d.arcs[0].curve).r = 2.0 + 1e-5;
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcNotOnBisector);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 0);
  EXPECT_NEAR(std::hypot(v->x + 1, v->y), 2.0, 1e-4);
}

TEST(CorruptedDiagrams, ShiftedCircleCentre) {
  Diagram d = weighted_lens();
  std::get<Circle>(d.arcs[1].curve).cy += 1e-4;
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcNotOnBisector);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 1);
}

TEST(CorruptedDiagrams, ShiftedLineIsOffBisector) {
  Diagram d = two_equal_sites();
  std::get<Line>(d.arcs[0].curve).x = 1.001;
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcNotOnBisector);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 0);
  // Probes find the true bisector x = 1 uncovered.
  const auto u = first_of(r, ViolationKind::BoundaryNotCovered);
  ASSERT_TRUE(u) << r.brief();
  EXPECT_NEAR(u->x, 1.0, 1e-9);
}

TEST(CorruptedDiagrams, DeletedSegmentLeavesBoundaryUncovered) {
  Diagram d = rhombus();
  clear_faces(d);
  d.arcs.erase(d.arcs.begin());  // the segment y = 0 from (-4/3, 0) to (4/3, 0)
  const CheckReport r = check_diagram(d);
  ASSERT_GT(r.count(ViolationKind::BoundaryNotCovered), 0u) << r.brief();
  for (const Violation& v : r.violations) {
    ASSERT_EQ(v.kind, ViolationKind::BoundaryNotCovered) << v.message;
    EXPECT_NEAR(v.y, 0.0, 1e-9);
    EXPECT_LE(std::abs(v.x), 4.0 / 3);
  }
}

// The rounding allowed for a huge circle's numbers (64 ulps of 3e13: ~0.4 here) does not hide a
// missing arc, nor one moved by about the site spacing.
TEST(CorruptedDiagrams, HugeCircleDeletedOrMoved) {
  Diagram d = nearly_equal_weights();
  clear_faces(d);
  Diagram moved = d;
  std::get<Circle>(moved.arcs[0].curve).cx += 1.0;
  d.arcs.clear();
  const CheckReport r = check_diagram(d);
  ASSERT_GT(r.count(ViolationKind::BoundaryNotCovered), 0u) << r.brief();
  // Every report lies on the true bisector, between the sites (it passes near their midpoint).
  for (const Violation& v : r.violations) EXPECT_LT(std::hypot(v.x - 0.35, v.y - 0.15), 2.0) << v.message;
  EXPECT_FALSE(check_diagram(moved).ok());
}

TEST(CorruptedDiagrams, DeletedRayLeavesBoundaryUncovered) {
  Diagram d = square();
  d.arcs.erase(d.arcs.begin() + 1);  // the ray from (1,1) along +x
  const CheckReport r = check_diagram(d);
  ASSERT_GT(r.count(ViolationKind::BoundaryNotCovered), 0u) << r.brief();
  for (const Violation& v : r.violations) {
    ASSERT_EQ(v.kind, ViolationKind::BoundaryNotCovered) << v.message;
    EXPECT_NEAR(v.y, 1.0, 1e-9);
    EXPECT_GE(v.x, 1.0);
  }
}

TEST(CorruptedDiagrams, DeletedLatticeSegment) {
  Diagram d = lattice(5);
  // Arc 6 is between sites (1,1) and (2,1): x = 1.5 from node (1,0) at y 0.5 to node (1,1) at 1.5.
  ASSERT_EQ(d.arcs[6].left_site, 6);
  d.arcs.erase(d.arcs.begin() + 6);
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::BoundaryNotCovered);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_NEAR(v->x, 1.5, 1e-9);
  EXPECT_GE(v->y, 0.5 - 1e-9);
  EXPECT_LE(v->y, 1.5 + 1e-9);
  EXPECT_EQ(r.total_violations(), r.count(ViolationKind::BoundaryNotCovered)) << r.brief();
}

TEST(CorruptedDiagrams, AddedCrossingArc) {
  // A piece of the s2|s3 bisector x = 0 from (0,-0.5) to (0,0.5) crosses the segment at (0,0).
  Diagram d = rhombus();
  clear_faces(d);
  d.nodes.push_back(Node{0, -0.5});
  d.nodes.push_back(Node{0, 0.5});
  d.arcs.push_back(line_arc(2, 3, Line{0, -0.5, 0, 1}, 2, 3));
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcsCross);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_TRUE(near(*v, 0.0, 0.0, 1e-12));
  EXPECT_EQ(v->arc, 0);
  EXPECT_EQ(v->other_arc, 5);
}

TEST(CorruptedDiagrams, DuplicatedArcOverlaps) {
  Diagram d = rhombus();
  clear_faces(d);
  d.arcs.push_back(d.arcs[0]);
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcsCross);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->other_arc, 5);
  EXPECT_EQ(r.total_violations(), 1u) << r.brief();
}

TEST(CorruptedDiagrams, RayExtendedIntoThirdRegion) {
  // The s0|s1 ray made a whole line: above the node it runs through s2's region.
  Diagram d = triangle();
  d.arcs[0].from = kNone;
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcSiteCloser);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 0);
  EXPECT_EQ(v->site, 2);
  EXPECT_NEAR(v->x, 2.0, 1e-12);
  EXPECT_GT(v->y, 1.0);
  EXPECT_EQ(r.count(ViolationKind::ArcsCross), 0u) << "the other rays end at the node";
}

TEST(CorruptedDiagrams, NewSiteNearNode) {
  Diagram d = triangle();
  d.sites.push_back(site(2.0, 1.2));
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::NodeSiteCloser);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->node, 0);
  EXPECT_EQ(v->site, 3);
  EXPECT_GT(r.count(ViolationKind::BoundaryNotCovered), 0u);
}

TEST(CorruptedDiagrams, OutOfRangeIndices) {
  Diagram d = triangle();
  d.arcs[1].left_site = 7;
  d.arcs[2].from = 9;
  const CheckReport r = check_diagram(d);
  std::vector<int> bad_arcs;
  for (const Violation& v : r.violations)
    if (v.kind == ViolationKind::BadIndex) bad_arcs.push_back(v.arc);
  EXPECT_EQ(bad_arcs, (std::vector<int>{1, 2})) << r.brief();
  // The sound arc is still checked; the broken ones leave boundaries uncovered.
  EXPECT_EQ(r.arc_samples_checked, static_cast<std::size_t>(CheckOptions{}.samples_per_arc));
}

TEST(CorruptedDiagrams, ReversedSegment) {
  Diagram d = rhombus();
  std::swap(d.arcs[0].from, d.arcs[0].to);  // now from R to L, but still along +x
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::LineArcReversed);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 0);
  EXPECT_TRUE(near(*v, 4.0 / 3, 0.0, 1e-12));
}

TEST(CorruptedDiagrams, EndNodeOffCurve) {
  Diagram d = rhombus();
  d.arcs[3].curve = Line{4.0 / 3 + 1e-3, 0, 1, 3};  // R's upper ray, shifted right
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcEndNotOnCurve);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 3);
  EXPECT_EQ(v->node, 1);
}

TEST(CorruptedDiagrams, BadSiteAndCurve) {
  Diagram d = square();
  d.sites[2].weight = 0.0;
  d.arcs[0].curve = Line{1, 1, 0, 0};
  const CheckReport r = check_diagram(d);
  const auto s = first_of(r, ViolationKind::BadSite);
  ASSERT_TRUE(s) << r.brief();
  EXPECT_EQ(s->site, 2);
  const auto c = first_of(r, ViolationKind::BadCurve);
  ASSERT_TRUE(c) << r.brief();
  EXPECT_EQ(c->arc, 0);
}

TEST(CorruptedDiagrams, FaceOnWrongSide) {
  Diagram d = two_equal_sites();
  std::swap(d.faces[0].site, d.faces[1].site);
  const CheckReport r = check_diagram(d);
  EXPECT_EQ(r.count(ViolationKind::FaceInconsistent), 2u) << r.brief();
  EXPECT_EQ(r.total_violations(), 2u) << r.brief();
}

TEST(CorruptedDiagrams, FaceCycleBroken) {
  Diagram d = rhombus();
  d.half_arcs[d.cycles[d.faces[0].cycles_begin].begin + 1] = HalfArc{4, true};  // R's lower ray: right start, but site 3's
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::FaceInconsistent);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->face, 0);
  EXPECT_EQ(v->arc, 4);
}

TEST(CorruptedDiagrams, FrameArcWithWrongSite) {
  Diagram d = clipped_two_sites();
  d.arcs[2].left_site = 0;  // the right edge x = 3 belongs to site 1
  const CheckReport r = check_diagram(d);
  const auto v = first_of(r, ViolationKind::ArcSiteCloser);
  ASSERT_TRUE(v) << r.brief();
  EXPECT_EQ(v->arc, 2);
  EXPECT_EQ(v->site, 1);
  EXPECT_NEAR(v->x, 3.0, 1e-12);
}

TEST(CorruptedDiagrams, ReportIsCappedButCounted) {
  Diagram d = lattice(4);
  for (Arc& a : d.arcs) std::swap(a.left_site, a.right_site);
  CheckOptions o;
  o.max_reported = 5;
  const CheckReport r = check_diagram(d, o);
  EXPECT_EQ(r.violations.size(), 5u);
  EXPECT_EQ(r.count(ViolationKind::ArcSidesSwapped), d.arcs.size());
  EXPECT_FALSE(r.ok());
}

}  // namespace
}  // namespace covmap::check::testing
