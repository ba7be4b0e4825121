// Graphs without constraining nodes (seed paper 5, §3): disjoint, nested circles and parallel lines.
// Round trips through the engine — islands of light sites inside heavier ones give MWVDs whose arcs
// are whole circles — must be recognised as bisector graphs whose reconstruction recomputes to the
// same diagram, with the true site of the root face inside the reported region. Hand-made graphs
// whose region is empty (paper Figure 4c) must be rejected, naming the face.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mobius/feasible_region.h"
#include "recognition/recognize.h"
#include "voronoi/engine.h"

namespace covmap::recognition {
namespace {


// Islands: each new site sits near a parent site, lighter, so that its region is a small disk
// inside the parent's region; children nest inside children up to three levels (each level is
// ~10 times smaller: deeper nests reach radii below the graphs' relative precision of 1e-7).
// `roots` heavy sites of equal weight on the x-axis make parallel bisector lines.
std::vector<Site> nested_sites(std::mt19937_64& rng, int roots, int islands) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), light(0.1, 0.4);
  std::vector<Site> s;
  std::vector<double> reach;  // how far from its site a child may be placed
  std::vector<int> depth;
  for (int k = 0; k < roots; ++k) {
    s.push_back({"r" + std::to_string(k), 100.0 * k, 0.0, 1.0});
    reach.push_back(30.0);
    depth.push_back(0);
  }
  for (int i = 0; i < islands; ++i) {
    std::uniform_int_distribution<int> pick(0, static_cast<int>(s.size()) - 1);
    int parent = pick(rng);
    while (depth[parent] >= 3) parent = pick(rng);
    const Site& p = s[parent];
    const double dist = reach[parent] * (0.4 + 0.6 * std::abs(u(rng)));
    const double angle = 3.14159265358979 * u(rng);
    const double k = light(rng);
    s.push_back({"i" + std::to_string(i), p.x + dist * std::cos(angle), p.y + dist * std::sin(angle), p.weight * k});
    // The child's disk has radius k·dist/(1 - k²) about a centre near it; grandchildren stay inside.
    reach.push_back(0.5 * k * dist);
    depth.push_back(depth[parent] + 1);
  }
  return s;
}

// The site that owns the face on the left of a half-arc, read from the engine's labels.
int owner_on_left(const Diagram& labelled, const HalfArc& h) {
  const Arc& a = labelled.arcs[h.arc];
  return h.forward ? a.left_site : a.right_site;
}

int run_round_trips(int roots, int trials, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  int checked = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const auto sites = nested_sites(rng, roots, 1 + trial % 12);
    const Diagram d = voronoi::build_diagram(sites);
    if (!d.nodes.empty()) continue;  // islands happened to touch: not this test's subject
    const Reconstruction r = recognize(d);
    EXPECT_TRUE(r.bisector_graph) << "trial " << trial << ": " << r.reason;
    if (!r.bisector_graph) continue;
    EXPECT_FALSE(r.unique);
    EXPECT_TRUE(r.region.has_value()) << "trial " << trial;
    EXPECT_EQ(r.voronoi, MwvdAnswer::kYes) << "trial " << trial << ": "
                                << (r.voronoi_differences.empty() ? "" : r.voronoi_differences[0].message);
    EXPECT_EQ(r.sites.size(), sites.size()) << "trial " << trial;
    if (!r.region) continue;
    // The true site of the root face lies in the region (up to rounding of the bounds).
    const auto& face = r.graph.faces[r.region->face];
    const FaceCycles cycles = face_cycles(d, face);
    if (!cycles.empty() && !cycles.front().empty()) {
      const int truth = owner_on_left(d, cycles.front().front());
      EXPECT_NE(truth, kNone);
      if (truth == kNone) continue;
      const mobius::Complex z(sites[truth].x, sites[truth].y);
      for (const mobius::GeneralizedCircle& b : r.region->bounds)
        EXPECT_GT(signed_distance_inside(b, z), -1e-9 * 100.0 * roots) << "trial " << trial;
    }
    // The representative is inside every bound by the stated margin.
    const mobius::Complex rep(r.region->representative.x, r.region->representative.y);
    for (const mobius::GeneralizedCircle& b : r.region->bounds)
      EXPECT_GE(signed_distance_inside(b, rep), r.region->margin * (1 - 1e-9)) << "trial " << trial;
    ++checked;
  }
  return checked;
}

TEST(NestedCircles, IslandsAroundOneSiteRoundTrip) {
  EXPECT_GT(run_round_trips(1, 400, 21), 200);
}

TEST(NestedCircles, IslandsBetweenParallelLinesRoundTrip) {
  EXPECT_GT(run_round_trips(3, 300, 22), 150);
}

Diagram circles_only(const std::vector<Circle>& circles) {
  Diagram g;
  for (const auto& c : circles) {
    Arc a;
    a.curve = c;
    g.arcs.push_back(a);
  }
  return g;
}

// Paper Figure 4c: in each of two disjoint circles a concentric circle. Going in through C and out
// through the inner circle confines the outer site to the annulus between C and C inverted; two
// annuli that do not meet leave no place for it.
TEST(NestedCircles, DisjointSolutionSetsAreRejected) {
  const Diagram g = circles_only({{0, 0, 1}, {0, 0, 0.5}, {10, 0, 1}, {10, 0, 0.5}});
  const Reconstruction r = recognize(g);
  EXPECT_FALSE(r.bisector_graph);
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_NE(r.failure->face, kNone);
  EXPECT_NE(r.reason.find("face"), std::string::npos) << r.reason;
}

// The same pair closer together: the annuli 1 < |z| < 2 and 1 < |z - 2.5| < 2 overlap, and any
// point there gives sites whose MWVD is the graph (paper 5, §3.2).
TEST(NestedCircles, OverlappingSolutionSetsAreAccepted) {
  const Diagram g = circles_only({{0, 0, 1}, {0, 0, 0.5}, {2.5, 0, 1}, {2.5, 0, 0.5}});
  const Reconstruction r = recognize(g);
  ASSERT_TRUE(r.bisector_graph) << r.reason;
  ASSERT_TRUE(r.region.has_value());
  const mobius::Complex rep(r.region->representative.x, r.region->representative.y);
  EXPECT_GT(std::abs(rep), 1.0);
  EXPECT_LT(std::abs(rep), 2.0);
  EXPECT_GT(std::abs(rep - mobius::Complex(2.5, 0)), 1.0);
  EXPECT_LT(std::abs(rep - mobius::Complex(2.5, 0)), 2.0);
  EXPECT_EQ(r.voronoi, MwvdAnswer::kYes);
  EXPECT_EQ(r.sites.size(), 5u);
}

}  // namespace
}  // namespace covmap::recognition
