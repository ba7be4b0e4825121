// merge_degree_two_nodes: splitting arcs of a diagram at inserted nodes of degree 2 and merging
// them back gives the original graph (compare_graphs), and each merge is reported.
#include <gtest/gtest.h>

#include <random>

#include "recognition/compare.h"
#include "recognition/graph_repair.h"
#include "recognition/recognize.h"
#include "voronoi/arc_path.h"
#include "voronoi/engine.h"

namespace covmap::recognition {
namespace {

// `d` with up to `count` bounded arcs split at their midpoints (new nodes of degree 2); the second
// half stored reversed when `reverse_second`, to exercise orientation handling. Returns the splits.
int split_arcs(const Diagram& d, Diagram& split, int count, bool reverse_second) {
  split = d;
  int splits = 0;
  for (std::size_t a = 0; a < d.arcs.size() && splits < count; ++a) {
    const Arc arc = d.arcs[a];
    if (arc.from == kNone || arc.to == kNone || arc.from == arc.to) continue;
    const voronoi::ArcPathView p = voronoi::arc_path(arc, d.nodes);
    const Point mid = p.at(0.5 * (p.s0 + p.s1));
    const int node = static_cast<int>(split.nodes.size());
    split.nodes.push_back({mid.x, mid.y});
    Arc second = arc;
    split.arcs[a].to = node;
    second.from = node;
    split.arcs.push_back(reverse_second ? reversed(second) : second);
    ++splits;
  }
  return splits;
}

TEST(GraphRepair, SplitArcsAreJoinedBack) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0), w(1.0, 2.0);
  std::vector<Site> sites;
  for (int i = 0; i < 25; ++i) sites.push_back({std::to_string(i), u(rng), u(rng), w(rng)});
  const Diagram d = voronoi::build_diagram(sites);
  Diagram split;
  const int splits = split_arcs(d, split, 10, true);
  ASSERT_EQ(splits, 10);
  EXPECT_EQ(split.nodes.size(), d.nodes.size() + 10);  // geometrically the same graph, 10 extra nodes
  const auto repairs = merge_degree_two_nodes(split, 1e-9);
  EXPECT_EQ(repairs.size(), 10u);
  const Comparison c = compare_graphs(d, split);
  EXPECT_TRUE(c.equal()) << c.brief();
}

// The preparation every caller shares: a diagram far from the origin (coordinates ~1e6, where an
// absolute merge tolerance would be wrong by orders of magnitude), its arcs split at degree-2
// nodes and its labels kept, is recognised as the MWVD of sites that reproduce it.
TEST(GraphRepair, PreparedInputIsRecognisedLikeTheUnsplitDiagram) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(1e6, 1e6 + 1000.0), w(1.0, 2.0);
  std::vector<Site> sites;
  for (int i = 0; i < 30; ++i) sites.push_back({std::to_string(i), u(rng), u(rng), w(rng)});
  const Diagram d = voronoi::build_diagram(sites);
  Diagram split;
  const int splits = split_arcs(d, split, 6, false);
  ASSERT_EQ(splits, 6);
  const auto repairs = prepare_input_graph(split);
  EXPECT_EQ(repairs.size(), 6u);
  // The sites and labels stay (recognize() compares them with its reconstruction); faces go.
  EXPECT_EQ(split.sites.size(), sites.size());
  for (const Arc& a : split.arcs) EXPECT_TRUE(a.left_site != kNone && a.right_site != kNone);
  EXPECT_TRUE(split.faces.empty());
  EXPECT_EQ(split.arcs.size(), d.arcs.size());
  const Reconstruction r = recognize(split);
  EXPECT_TRUE(r.bisector_graph) << r.reason;
  EXPECT_EQ(r.sites.size(), sites.size());
  ASSERT_TRUE(r.input_sites.has_value());
  EXPECT_TRUE(r.input_sites->agree) << r.input_sites->differences.front().message;
}

}  // namespace
}  // namespace covmap::recognition
