// compare_graphs: a diagram equals itself (and a copy with renumbered nodes and reversed arcs);
// deleting an arc, moving a node or changing a radius is reported at the right place.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "recognition/compare.h"
#include "voronoi/engine.h"

namespace covmap::recognition {
namespace {


Diagram sample(int seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), w(1.0, 2.0);
  std::vector<Site> s;
  for (int i = 0; i < 25; ++i) s.push_back({std::to_string(i), u(rng), u(rng), w(rng)});
  return voronoi::build_diagram(s);
}

TEST(Compare, EqualToARenumberedCopy) {
  const Diagram a = sample(1);
  Diagram b = a;
  // The same graph with nodes and arcs listed in reverse order.
  const int n = static_cast<int>(b.nodes.size());
  std::reverse(b.nodes.begin(), b.nodes.end());
  for (auto& arc : b.arcs) {
    if (arc.from != kNone) arc.from = n - 1 - arc.from;
    if (arc.to != kNone) arc.to = n - 1 - arc.to;
  }
  std::reverse(b.arcs.begin(), b.arcs.end());
  const Comparison c = compare_graphs(a, b);
  EXPECT_TRUE(c.equal()) << c.brief();
  EXPECT_EQ(c.nodes_matched, a.nodes.size());
  EXPECT_EQ(c.arcs_matched, a.arcs.size());
}

TEST(Compare, MissingArcMovedNodeAndWrongRadiusAreLocated) {
  const Diagram a = sample(2);
  {
    Diagram b = a;
    b.arcs.erase(b.arcs.begin() + 5);
    const Comparison c = compare_graphs(a, b);
    ASSERT_EQ(c.differences.size(), 1u) << c.brief();
    EXPECT_EQ(c.differences[0].kind, DifferenceKind::ArcOnlyInA);
    EXPECT_EQ(c.differences[0].index, 5);
  }
  {
    Diagram b = a;
    b.nodes[3].x += 1e-3;
    const Comparison c = compare_graphs(a, b);
    bool node_reported = false;
    for (const auto& d : c.differences)
      if (d.kind == DifferenceKind::NodeOnlyInB && d.index == 3) node_reported = true;
    EXPECT_TRUE(node_reported) << c.brief();
  }
  {
    Diagram b = a;
    for (auto& arc : b.arcs)
      if (auto* circle = std::get_if<Circle>(&arc.curve)) {
        circle->r *= 1.001;
        break;
      }
    const Comparison c = compare_graphs(a, b);
    EXPECT_EQ(c.differences.size(), 2u) << c.brief();  // the arc only in a, its changed copy in b
  }
}

// Node positions are hashed by grid cell: far from the origin (here 10^6 extents, ~10^13 cells) the
// cell numbers times the hash factors overflowed a signed 64-bit integer, and a NaN node (as the
// engine makes for some exactly degenerate inputs after rounding) was converted to an integer
// (both undefined: scripts/sanitize.sh aborted in RoundTrip.GridSitesWithHighDegreeNodes…).
TEST(Compare, FarFromTheOriginAndNodesWithoutAPosition) {
  Diagram a = sample(3);
  for (auto& s : a.sites) s.x += 1e6, s.y += 1e6;
  for (auto& v : a.nodes) v.x += 1e6, v.y += 1e6;
  for (auto& arc : a.arcs) {
    if (auto* circle = std::get_if<Circle>(&arc.curve)) circle->cx += 1e6, circle->cy += 1e6;
    if (auto* line = std::get_if<Line>(&arc.curve)) line->x += 1e6, line->y += 1e6;
  }
  Diagram b = a;
  const Comparison same = compare_graphs(a, b);
  EXPECT_TRUE(same.equal()) << same.brief();
  EXPECT_EQ(same.nodes_matched, a.nodes.size());
  EXPECT_EQ(same.arcs_matched, a.arcs.size());

  b.nodes.push_back({std::nan(""), std::nan("")});
  const Comparison c = compare_graphs(a, b);
  EXPECT_EQ(c.nodes_matched, a.nodes.size());
  ASSERT_EQ(c.differences.size(), 1u) << c.brief();
  EXPECT_EQ(c.differences[0].kind, DifferenceKind::NodeOnlyInB);
  EXPECT_EQ(c.differences[0].index, static_cast<int>(a.nodes.size()));
}

}  // namespace
}  // namespace covmap::recognition

namespace covmap::recognition {
namespace {

// A node drawn as two distinct nodes at the same point, joined by an arc of length zero (as the
// engine draws a degenerate node after rounding): compare_graphs read that arc as a full circle
// (voronoi/arc_path.cpp: distinct nodes at the same angle) while the checker read it as length
// zero, and reported a full circle that was not there. One reading now (core/arc_sweep.h): the
// graphs are equal.
TEST(Compare, ArcOfLengthZeroBetweenTwoNodesAtOnePointIsNoFullCircle) {
  const Diagram a = sample(4);
  Diagram b = a;
  int arc = kNone;
  for (std::size_t k = 0; k < b.arcs.size() && arc == kNone; ++k)
    if (std::holds_alternative<Circle>(b.arcs[k].curve) && b.arcs[k].from != kNone && b.arcs[k].from != b.arcs[k].to)
      arc = static_cast<int>(k);
  ASSERT_NE(arc, kNone);
  const int v = b.arcs[arc].to;
  const int twin = static_cast<int>(b.nodes.size());
  b.nodes.push_back(b.nodes[v]);
  Arc zero = b.arcs[arc];
  zero.from = v;
  zero.to = twin;
  b.arcs[arc].to = twin;  // the arc now ends at the twin, which the zero-length arc joins to v
  b.arcs.push_back(zero);
  const Comparison c = compare_graphs(a, b);
  EXPECT_TRUE(c.equal()) << c.brief();
}

}  // namespace
}  // namespace covmap::recognition
