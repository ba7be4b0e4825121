// Round trips through the engine: sites → MWVD → strip the sites → recognize → the same sites and
// weight ratios. A face with three degree-3 nodes fixes the positions completely (Lemma 6), and
// weights up to one common factor, so positions are compared directly and weights after
// normalising both sets to a largest weight of 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "recognition/recognize.h"
#include "voronoi/engine.h"

namespace covmap::recognition {
namespace {


std::vector<Site> random_sites(std::mt19937_64& rng, int n, bool equal_weights) {
  std::uniform_real_distribution<double> u(0.0, 1.0), w(1.0, 2.0);
  std::vector<Site> s;
  for (int i = 0; i < n; ++i) s.push_back({std::to_string(i), u(rng), u(rng), equal_weights ? 1.0 : w(rng)});
  return s;
}

// Every original site (that owns a face) must be matched by a reconstructed one, at the same place
// with the same normalised weight.
void expect_same_sites(const std::vector<Site>& original, const Reconstruction& r, double tol) {
  double wmax = 0;
  for (const Site& s : original) wmax = std::max(wmax, s.weight);
  for (const Site& s : original) {
    double best = INFINITY;
    const Site* match = nullptr;
    for (const Site& t : r.sites) {
      const double d = std::hypot(s.x - t.x, s.y - t.y);
      if (d < best) best = d, match = &t;
    }
    ASSERT_NE(match, nullptr);
    EXPECT_LT(best, tol) << "site " << s.id;
    EXPECT_NEAR(match->weight, s.weight / wmax, 1e-9 * s.weight / wmax) << "site " << s.id;
  }
  EXPECT_EQ(r.sites.size(), original.size());
}

TEST(RoundTrip, WeightedSitesAreRecovered) {
  std::mt19937_64 rng(11);
  int recognised = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const auto sites = random_sites(rng, 6 + trial % 30, false);
    Diagram d = voronoi::build_diagram(sites);
    const Reconstruction r = recognize(d);
    ASSERT_TRUE(r.bisector_graph) << "trial " << trial << ": " << r.reason;
    if (!r.unique) continue;  // a family: the originals are one member, compared elsewhere
    expect_same_sites(sites, r, 1e-9);
    EXPECT_EQ(r.voronoi, MwvdAnswer::kYes) << "trial " << trial << ": "
                                << (r.voronoi_differences.empty() ? "" : r.voronoi_differences[0].message);
    ++recognised;
  }
  EXPECT_GT(recognised, 150);
}

TEST(RoundTrip, EqualWeightsAreRecovered) {
  std::mt19937_64 rng(12);
  int recognised = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const auto sites = random_sites(rng, 6 + trial % 30, true);
    const Reconstruction r = recognize(voronoi::build_diagram(sites));
    ASSERT_TRUE(r.bisector_graph) << "trial " << trial << ": " << r.reason;
    expect_same_sites(sites, r, 1e-9);
    ++recognised;
  }
  EXPECT_GT(recognised, 80);
}

// Orphan-rich diagrams: weights spread over a factor of 30 give heavy sites regions in several
// pieces (orphan faces without their own site). Every face must get the site that drew it: the
// reconstructed site of each face equals the engine's label for it, and the orphans' pieces share
// one site.
TEST(RoundTrip, OrphanRichDiagramsAreRecovered) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(0.0, 1.0), logw(0.0, std::log(30.0));
  int with_orphans = 0, checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Site> sites;
    const int n = 10 + trial % 40;
    for (int i = 0; i < n; ++i) sites.push_back({std::to_string(i), u(rng), u(rng), std::exp(logw(rng))});
    const Diagram d = voronoi::build_diagram(sites);
    const int orphans = static_cast<int>(std::count_if(d.faces.begin(), d.faces.end(), [](const auto& f) { return f.orphan; }));
    if (orphans == 0) continue;
    ++with_orphans;
    const Reconstruction r = recognize(d);
    ASSERT_TRUE(r.bisector_graph) << "trial " << trial << ": " << r.reason;
    if (!r.unique) continue;
    expect_same_sites(sites, r, 1e-8);
    // Each traced face's site is the one the engine labelled it with (matched by position).
    for (std::size_t f = 0; f < r.graph.faces.size(); ++f) {
      const auto& face = r.graph.faces[f];
      const FaceCycles cycles = face_cycles(r.graph, face);
      if (cycles.empty() || cycles.front().empty() || r.face_site[f] == kNone) continue;
      const HalfArc h = cycles.front().front();
      const Arc& a = d.arcs[h.arc];
      const int truth = h.forward ? a.left_site : a.right_site;
      const Site& got = r.sites[r.face_site[f]];
      EXPECT_LT(std::hypot(got.x - sites[truth].x, got.y - sites[truth].y), 1e-8) << "trial " << trial << " face " << f;
    }
    EXPECT_EQ(r.voronoi, MwvdAnswer::kYes) << "trial " << trial << ": "
                                << (r.voronoi_differences.empty() ? "" : r.voronoi_differences[0].message);
    ++checked;
  }
  EXPECT_GT(with_orphans, 30);
  EXPECT_GT(checked, 25);
}

// A graph that is not a bisector graph: move one node (and the arcs' ends with it) so the arcs no
// longer meet on common bisectors; recognition must say no and name an arc or face.
TEST(Negative, ShiftedArcIsRejected) {
  std::mt19937_64 rng(13);
  int rejected = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const auto sites = random_sites(rng, 12, false);
    Diagram d = voronoi::build_diagram(sites);
    // Enlarge one circle arc's radius by 1%: it is then no bisector of mirror-image sites.
    for (auto& a : d.arcs)
      if (auto* c = std::get_if<Circle>(&a.curve); c && a.from != kNone) {
        c->r *= 1.01;
        break;
      }
    const Reconstruction r = recognize(d);
    EXPECT_FALSE(r.bisector_graph) << "trial " << trial;
    if (!r.bisector_graph) {
      ASSERT_TRUE(r.failure.has_value());
      EXPECT_TRUE(r.failure->arc != kNone || r.failure->face != kNone);
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 30);
}

}  // namespace
}  // namespace covmap::recognition

#include "voronoi/clip.h"

namespace covmap::recognition {
namespace {

// Clipped maps: frame arcs are no bisectors; the sites of faces cut by the frame still come from
// interior nodes and propagation. Sites whose regions meet the window are recovered; the MWVD
// check clips the recomputed diagram to the same frame.
TEST(RoundTrip, ClippedDiagramsAreRecovered) {
  std::mt19937_64 rng(31);
  const std::vector<Point> window = {{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.8}, {0.2, 0.8}};
  int recognised = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const auto sites = random_sites(rng, 40, trial % 3 == 0);
    const Diagram d = voronoi::clip_diagram(voronoi::build_diagram(sites), window);
    const Reconstruction r = recognize(d);
    ASSERT_TRUE(r.bisector_graph) << "trial " << trial << ": " << r.reason;
    EXPECT_EQ(r.voronoi, MwvdAnswer::kYes) << "trial " << trial << ": "
                                << (r.voronoi_differences.empty() ? "" : r.voronoi_differences[0].message);
    // Every reconstructed site is one of the originals (same place, same relative weight).
    for (const auto& t : r.sites) {
      double best = INFINITY;
      const Site* match = nullptr;
      for (const Site& s : sites) {
        const double dd = std::hypot(s.x - t.x, s.y - t.y);
        if (dd < best) best = dd, match = &s;
      }
      ASSERT_LT(best, 1e-9) << "trial " << trial;
      ASSERT_NE(match, nullptr);
    }
    // Weight ratios between reconstructed sites equal the originals'.
    for (std::size_t a = 0; a + 1 < r.sites.size(); ++a) {
      auto orig = [&](const Site& t) -> double {
        for (const Site& s : sites)
          if (std::hypot(s.x - t.x, s.y - t.y) < 1e-9) return s.weight;
        return NAN;
      };
      const double ratio_rec = r.sites[a].weight / r.sites[a + 1].weight;
      const double ratio_orig = orig(r.sites[a]) / orig(r.sites[a + 1]);
      EXPECT_NEAR(ratio_rec, ratio_orig, 1e-9 * ratio_orig) << "trial " << trial;
    }
    ++recognised;
  }
  EXPECT_GT(recognised, 80);
}

}  // namespace
}  // namespace covmap::recognition

#include "../voronoi/site_families.h"

namespace covmap::recognition {
namespace {

// Degenerate inputs: integer grids with two weights give nodes of degree four and more, shared power
// lines and tangencies; the sites must still come back exactly.
TEST(RoundTrip, GridSitesWithHighDegreeNodesAreRecovered) {
  int recognised = 0, high_degree = 0, voronoi_yes = 0;
  for (int seed = 1; seed <= 60; ++seed) {
    const auto sites = voronoi::testing::make_sites(voronoi::testing::Family::Grid, 25, seed);
    const Diagram d = voronoi::build_diagram(sites);
    std::vector<int> degree(d.nodes.size(), 0);
    for (const auto& a : d.arcs)
      for (int v : {a.from, a.to})
        if (v != kNone) ++degree[v];
    if (std::any_of(degree.begin(), degree.end(), [](int k) { return k > 3; })) ++high_degree;
    const Reconstruction r = recognize(d);
    ASSERT_TRUE(r.bisector_graph) << "seed " << seed << ": " << r.reason;
    if (!r.unique) continue;
    expect_same_sites(sites, r, 1e-9);
    voronoi_yes += r.voronoi == MwvdAnswer::kYes;
    ++recognised;
  }
  EXPECT_GT(recognised, 40);
  // Known limit (docs/RECOGNITION.md): a few exactly degenerate grids are redrawn from the
  // reconstructed sites (exact only to ~1e-15) with a circle looping through a tangency node that
  // the comparison does not identify with the input's: at most 4 of the 60 seeds are allowed it.
  EXPECT_GE(voronoi_yes, recognised - 4);
  EXPECT_GT(high_degree, 10) << "the family should produce nodes of degree > 3";
}

// Three sites: every face has exactly two nodes, and both nodes lie on the same three bisector
// circles, so going around either node is the same composition of inversions: the two solution
// circles of a face coincide and the sites form a one-parameter family (paper 5, §4.2). Any member
// must redraw the same graph.
TEST(RoundTrip, FacesWithTwoNodesGiveAFamily) {
  const std::vector<Site> sites = {{"a", 0, 0, 1}, {"b", 1, 0, 1.5}, {"c", 0.5, 0.8, 1.2}};
  const Diagram d = voronoi::build_diagram(sites);
  const Reconstruction r = recognize(d);
  ASSERT_TRUE(r.bisector_graph) << r.reason;
  EXPECT_FALSE(r.unique);
  ASSERT_EQ(r.sites.size(), 3u);
  EXPECT_EQ(r.voronoi, MwvdAnswer::kYes) << (r.voronoi_differences.empty() ? "" : r.voronoi_differences[0].message);
}

}  // namespace
}  // namespace covmap::recognition
