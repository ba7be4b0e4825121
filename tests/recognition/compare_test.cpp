// compare_graphs: a diagram equals itself (and a copy with renumbered nodes and reversed arcs);
// deleting an arc, moving a node or changing a radius is reported at the right place.
#include <gtest/gtest.h>

#include <algorithm>
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

}  // namespace
}  // namespace covmap::recognition
