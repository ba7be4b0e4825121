// Clipped diagrams: the checker (which restricts its probes to Diagram::clip) must accept them,
// every point of the polygon lies in exactly one face whose site owns it (brute force), and frame
// arcs cover the boundary exactly once.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "site_families.h"
#include "check/check.h"
#include "core/point_in_polygon.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"
#include "voronoi/faces.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi {
namespace {

using testing::Family;

const std::vector<Point> kRectangle = {{0.1, 0.15}, {0.85, 0.15}, {0.85, 0.9}, {0.1, 0.9}};
// Non-convex (an L with a notch), counter-clockwise.
const std::vector<Point> kNotched = {{0.05, 0.05}, {0.95, 0.05}, {0.95, 0.5}, {0.5, 0.5},
                                     {0.45, 0.95}, {0.05, 0.95}};

class ClipChecked : public ::testing::TestWithParam<Family> {};

TEST_P(ClipChecked, CheckerAndOwnershipAgree) {
  for (const auto* polygon : {&kRectangle, &kNotched}) {
    for (int seed = 1; seed <= 12; ++seed) {
      const auto sites = testing::make_sites(GetParam(), 30, seed);
      const Diagram clipped = clip_diagram(build_diagram(sites), *polygon);
      check::CheckOptions options;
      options.boundary_probes = 500;
      const check::CheckReport report = check::check_diagram(clipped, options);
      ASSERT_TRUE(report.ok()) << "seed " << seed << ": " << report.brief();
      // Frame arcs lie on the polygon and their total length is its perimeter.
      double frame = 0, perimeter = 0;
      for (std::size_t i = 0; i < polygon->size(); ++i) {
        const Point a = (*polygon)[i], b = (*polygon)[(i + 1) % polygon->size()];
        perimeter += std::hypot(b.x - a.x, b.y - a.y);
      }
      for (const Arc& a : clipped.arcs)
        if (a.frame) {
          const Node& p = clipped.nodes[a.from];
          const Node& q = clipped.nodes[a.to];
          frame += std::hypot(q.x - p.x, q.y - p.y);
        }
      EXPECT_NEAR(frame, perimeter, 1e-9) << "seed " << seed;
      // Every probe point inside the polygon is in exactly one face, of its brute-force owner.
      std::mt19937_64 rng(seed);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      for (int q = 0; q < 100; ++q) {
        const Point p{u(rng), u(rng)};
        if (!inside_ring(*polygon, p)) continue;
        int owner = 0;
        double best = 1e300;
        for (std::size_t s = 0; s < sites.size(); ++s) {
          const double v = std::hypot(p.x - sites[s].x, p.y - sites[s].y) / sites[s].weight;
          if (v < best) best = v, owner = static_cast<int>(s);
        }
        int count = 0, face_site = kNone;
        for (const Face& f : clipped.faces) {
          const FaceCycles cycles = face_cycles(clipped, f);
          bool in = cycle_contains(clipped, cycles.front(), p);
          for (std::size_t b = 1; b < cycles.size(); ++b)
            if (cycle_contains(clipped, cycles[b], p)) in = false;
          if (in) ++count, face_site = f.site;
        }
        ASSERT_EQ(count, 1) << "seed " << seed << " at (" << p.x << ", " << p.y << ")";
        EXPECT_EQ(face_site, owner);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Families, ClipChecked,
                         ::testing::Values(Family::UniformWeights, Family::EqualWeights,
                                           Family::WeightClasses),
                         [](const auto& info) { return testing::family_name(info.param); });

TEST(Clip, PolygonInsideOneRegionIsOneFrameFace) {
  const std::vector<Site> sites = {{"a", 0, 0, 1}, {"b", 10, 0, 1}};
  const std::vector<Point> square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const Diagram d = clip_diagram(build_diagram(sites), square);
  ASSERT_EQ(d.faces.size(), 1u);
  EXPECT_EQ(d.faces[0].site, 0);
  EXPECT_TRUE(d.faces[0].bounded);
  for (const Arc& a : d.arcs) EXPECT_TRUE(a.frame);
}

// Clipping's work is (arcs + nodes) × polygon vertices: a product beyond kMaxClipWork is refused
// before any work (a 10^6-vertex polygon would run for hours), one just below it
// is not refused by the check.
TEST(Clip, WorkBeyondTheLimitIsRefusedAtOnce) {
  const Diagram d = build_diagram(testing::make_sites(testing::Family::UniformWeights, 2000, 3));
  const double items = static_cast<double>(d.arcs.size() + d.nodes.size());
  const auto ring = [](std::size_t m) {
    std::vector<Point> polygon(m);
    for (std::size_t k = 0; k < m; ++k) {
      const double a = 2 * M_PI * static_cast<double>(k) / static_cast<double>(m);
      polygon[k] = {1e6 * std::cos(a), 1e6 * std::sin(a)};
    }
    return polygon;
  };
  const auto over = static_cast<std::size_t>(tolerance::kMaxClipWork / items) + 1;
  EXPECT_THROW(clip_diagram(d, ring(over)), ClipTooLarge);
  const Diagram small = build_diagram(testing::make_sites(testing::Family::UniformWeights, 5, 3));
  EXPECT_NO_THROW(clip_diagram(small, ring(1000)));
}

}  // namespace
}  // namespace covmap::voronoi
