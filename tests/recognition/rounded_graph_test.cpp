// Tolerant recognition: an exact diagram's arc graph written with d significant digits (every node
// coordinate, centre, radius, line point and direction rounded independently) is a bisector graph
// within a tolerance of that rounding, with sites whose errors are proportional to it; a graph
// inconsistent beyond the tolerance is rejected with how many arcs and nodes disagree and the worst.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "check/check.h"
#include "recognition/recognize.h"
#include "recognition_families.h"
#include "voronoi/engine.h"

namespace covmap::recognition {
namespace {

using testing::RecognitionFamily;

TEST(RoundedGraph, GraphsWithFewDigitsAreAcceptedWithinTheirRounding) {
  for (const int digits : {12, 9, 6}) {
    const double rounding = std::pow(10.0, 1 - digits);
    RecognitionOptions options;
    options.relative_tolerance = rounding;  // 10 units of the last written digit
    int accepted = 0, tried = 0;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const auto sites = testing::recognition_sites(RecognitionFamily::kRandom, 60, seed, {}, {1.0, 0.0, 0.0, 0.0});
      const Diagram drawn = voronoi::build_diagram(sites);
      if (!check::check_diagram(drawn).ok()) continue;
      ++tried;
      Diagram graph = drawn;
      testing::round_graph(graph, digits);
      const Reconstruction r = recognize(graph, options);
      const std::string what = std::to_string(digits) + " digits, seed " + std::to_string(seed);
      if (!r.bisector_graph) {
        ADD_FAILURE() << what << ": " << r.reason;
        continue;
      }
      ++accepted;
      EXPECT_EQ(r.residuals.arcs_beyond, 0) << what;
      ASSERT_FALSE(r.residuals.worst.empty()) << what;
      EXPECT_LE(r.residuals.worst.front().amount, r.residuals.worst.front().allowed) << what;
      if (!r.unique) continue;
      const auto e = testing::round_trip_error(sites, drawn, r);
      EXPECT_LE(e.position, 1e3 * rounding) << what;
      EXPECT_LE(e.weight, 1e4 * rounding) << what;
    }
    EXPECT_EQ(accepted, tried) << digits << " digits";
  }
}

// A rounded graph is within the tolerance of an MWVD (the one it was rounded from), so the MWVD
// check at that tolerance must answer "yes". 300 sites, ten seeds: they hold huge circles of
// nearly equal weights (rounded to 9 digits they miss their bisector by ~1e-9·r — "no" once) and
// orphan faces far out whose site the recognition keeps 4e-10 apart from its twin at 12 digits
// (seed 4: the twins' bisector split a region of the recomputed diagram — "no" once).
TEST(RoundedGraph, RoundedGraphsAreVoronoiDiagramsAtTheirTolerance) {
  for (const int digits : {12, 9, 6}) {
    RecognitionOptions options;
    options.relative_tolerance = std::pow(10.0, 1 - digits);  // 10 units of the last written digit
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const auto sites = testing::recognition_sites(RecognitionFamily::kRandom, 300, seed, {}, {1.0, 0.0, 0.0, 0.0});
      Diagram graph = voronoi::build_diagram(sites);
      if (!check::check_diagram(graph).ok()) continue;
      testing::round_graph(graph, digits);
      const Reconstruction r = recognize(std::move(graph), options);
      const std::string what = std::to_string(digits) + " digits, seed " + std::to_string(seed);
      ASSERT_TRUE(r.bisector_graph) << what << ": " << r.reason;
      EXPECT_EQ(r.voronoi, MwvdAnswer::kYes)
          << what << ": " << (r.voronoi_differences.empty() ? "" : r.voronoi_differences.front().message);
    }
  }
}

// Moving one arc's circle by far more than the tolerance: rejected, and the answer counts the
// disagreeing elements and names the worst, largest first.
TEST(RoundedGraph, InconsistencyBeyondTheToleranceIsCountedAndLocated) {
  const auto sites = testing::recognition_sites(RecognitionFamily::kRandom, 40, 7, {}, {1.0, 0.0, 0.0, 0.0});
  Diagram graph = voronoi::build_diagram(sites);
  int moved = kNone;
  for (std::size_t a = 0; a < graph.arcs.size() && moved == kNone; ++a)
    if (auto* c = std::get_if<Circle>(&graph.arcs[a].curve); c && graph.arcs[a].from != kNone) {
      c->r *= 1.01;
      moved = static_cast<int>(a);
    }
  ASSERT_NE(moved, kNone);
  const Reconstruction r = recognize(graph);
  ASSERT_FALSE(r.bisector_graph);
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_GE(r.residuals.nodes_beyond + r.residuals.arcs_beyond, 1);
  EXPECT_EQ(r.failure->nodes_beyond, r.residuals.nodes_beyond);
  EXPECT_EQ(r.failure->arcs_beyond, r.residuals.arcs_beyond);
  ASSERT_FALSE(r.residuals.worst.empty());
  for (std::size_t k = 1; k < r.residuals.worst.size(); ++k)
    EXPECT_GE(r.residuals.worst[k - 1].amount / r.residuals.worst[k - 1].allowed,
              r.residuals.worst[k].amount / r.residuals.worst[k].allowed);
  // The moved arc's end nodes are the ones off their curve.
  const Residual& worst = r.residuals.worst.front();
  ASSERT_EQ(worst.element, ResidualElement::kNode);
  EXPECT_TRUE(worst.index == graph.arcs[moved].from || worst.index == graph.arcs[moved].to) << worst.index;
  EXPECT_GT(worst.amount, worst.allowed);
}

}  // namespace
}  // namespace covmap::recognition
