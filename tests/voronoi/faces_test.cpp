// Faces traced from the engine's arcs, against a brute-force oracle: every random point lies in
// exactly one face, whose site is the point's weighted-nearest site; every site lies in exactly
// one of its own faces, the non-orphan one. Containment here is the test's own: each boundary cycle
// is flattened into a polygon (arcs sampled densely, rays cut at a far box), so it shares no code
// with the ray casting in voronoi/faces.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "canonical_faces.h"
#include "core/point_in_polygon.h"
#include "site_families.h"
#include "voronoi/engine.h"
#include "voronoi/faces.h"

namespace covmap::voronoi {
namespace {

using testing::Family;

int brute_owner(const std::vector<Site>& sites, Point p) {
  int best = 0;
  double bd = 1e300;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const double v = std::hypot(p.x - sites[i].x, p.y - sites[i].y) / sites[i].weight;
    if (v < bd) bd = v, best = static_cast<int>(i);
  }
  return best;
}

// The cycle as a polygon. Unbounded pieces are followed out to distance `far` and joined there
// counter-clockwise (the face is on the left), which is exact enough for points well inside.
std::vector<Point> flatten(const Diagram& d, std::span<const HalfArc> cycle, double far) {
  std::vector<Point> poly;
  auto angle_of = [](Point p) { return std::atan2(p.y, p.x); };
  for (std::size_t k = 0; k < cycle.size(); ++k) {
    const Arc& a = d.arcs[cycle[k].arc];
    std::vector<Point> pts;
    if (const Circle* c = std::get_if<Circle>(&a.curve)) {
      double a0 = 0, sweep = 2 * M_PI;
      if (a.from != kNone) {
        a0 = std::atan2(d.nodes[a.from].y - c->cy, d.nodes[a.from].x - c->cx);
        if (a.to != a.from) {
          const double a1 = std::atan2(d.nodes[a.to].y - c->cy, d.nodes[a.to].x - c->cx);
          sweep = std::fmod((a.ccw ? 1 : -1) * (a1 - a0) + 4 * M_PI, 2 * M_PI);
          if (sweep == 0) sweep = 2 * M_PI;
        }
      }
      const int steps = 256;
      for (int s = 0; s <= steps; ++s) {
        const double t = a0 + (a.ccw ? 1 : -1) * sweep * s / steps;
        pts.push_back({c->cx + c->r * std::cos(t), c->cy + c->r * std::sin(t)});
      }
    } else {
      const Line& l = std::get<Line>(a.curve);
      const double len = std::hypot(l.dx, l.dy);
      const Point u{l.dx / len, l.dy / len};
      auto param = [&](int n) { return (d.nodes[n].x - l.x) * u.x + (d.nodes[n].y - l.y) * u.y; };
      const double s0 = a.from == kNone ? -far : param(a.from);
      const double s1 = a.to == kNone ? far : param(a.to);
      pts.push_back({l.x + s0 * u.x, l.y + s0 * u.y});
      pts.push_back({l.x + s1 * u.x, l.y + s1 * u.y});
    }
    if (!cycle[k].forward) std::reverse(pts.begin(), pts.end());
    // Joining at infinity: go counter-clockwise along the far circle to the next piece's start.
    if (!poly.empty() && (std::hypot(pts.front().x, pts.front().y) > 0.5 * far) &&
        std::hypot(poly.back().x, poly.back().y) > 0.5 * far) {
      double from = angle_of(poly.back()), to = angle_of(pts.front());
      double span = std::fmod(to - from + 4 * M_PI, 2 * M_PI);
      for (int s = 1; s < 64; ++s) {
        const double t = from + span * s / 64;
        poly.push_back({far * std::cos(t), far * std::sin(t)});
      }
    }
    poly.insert(poly.end(), pts.begin(), pts.end());
  }
  if (poly.size() > 2 && std::hypot(poly.back().x, poly.back().y) > 0.5 * far &&
      std::hypot(poly.front().x, poly.front().y) > 0.5 * far) {
    double from = angle_of(poly.back()), to = angle_of(poly.front());
    double span = std::fmod(to - from + 4 * M_PI, 2 * M_PI);
    for (int s = 1; s < 64; ++s) {
      const double t = from + span * s / 64;
      poly.push_back({far * std::cos(t), far * std::sin(t)});
    }
  }
  return poly;
}

// Face membership: inside the outer boundary (if any) and outside every hole. An unbounded face's
// first boundary is outer when it runs through infinity; if its first cycle is closed and
// clockwise it is a hole. The polygon's orientation tells them apart.
bool in_face(const Diagram& d, const Face& f, Point p, double far) {
  bool inside = true;
  for (std::size_t b = 0; b < face_cycles(d, f).size(); ++b) {
    const auto poly = flatten(d, face_cycles(d, f)[b], far);
    double area = 0;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
      area += (poly[j].x * poly[i].y - poly[i].x * poly[j].y);
    const bool outer = area > 0;
    const bool in = inside_ring(poly, p);
    if (outer && !in) inside = false;
    if (!outer && in) inside = false;
  }
  return inside;
}

class FacesOracle : public ::testing::TestWithParam<Family> {};

TEST_P(FacesOracle, EveryPointInExactlyOneFaceOfItsOwner) {
  for (int seed = 1; seed <= 8; ++seed) {
    const auto sites = testing::make_sites(GetParam(), 25, seed);
    const Diagram d = build_diagram(sites);
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const Site& s : sites) {
      xmin = std::min(xmin, s.x), xmax = std::max(xmax, s.x);
      ymin = std::min(ymin, s.y), ymax = std::max(ymax, s.y);
    }
    const double scale = std::max(xmax - xmin, ymax - ymin);
    const double far = 1e3 * (scale + std::hypot(xmax, ymax) + std::hypot(xmin, ymin));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ux(xmin - 0.2 * scale, xmax + 0.2 * scale),
        uy(ymin - 0.2 * scale, ymax + 0.2 * scale);
    for (int q = 0; q < 150; ++q) {
      const Point p{ux(rng), uy(rng)};
      const int owner = brute_owner(sites, p);
      int containing = 0, containing_site = -1;
      for (const Face& f : d.faces)
        if (in_face(d, f, p, far)) ++containing, containing_site = f.site;
      ASSERT_EQ(containing, 1) << "seed " << seed << " point (" << p.x << ", " << p.y << ")";
      EXPECT_EQ(containing_site, owner) << "seed " << seed;
    }
    // Each site: exactly one non-orphan face, and the site lies in it.
    std::vector<int> own(sites.size(), 0);
    for (const Face& f : d.faces) {
      if (f.orphan) continue;
      ++own[f.site];
      EXPECT_TRUE(in_face(d, f, {sites[f.site].x, sites[f.site].y}, far)) << "seed " << seed;
    }
    for (std::size_t s = 0; s < sites.size(); ++s) EXPECT_EQ(own[s], 1) << "site " << s;
  }
}

INSTANTIATE_TEST_SUITE_P(Families, FacesOracle,
                         ::testing::Values(Family::UniformWeights, Family::EqualWeights,
                                           Family::WeightClasses, Family::SharedMaximum,
                                           Family::Grid),
                         [](const auto& info) { return testing::family_name(info.param); });

TEST(Faces, NestedRegionsGiveHolesAndOrphans) {
  // A light site inside a heavy one's region: a full-circle hole; two heavy equal sites and a light
  // one between them far away give an orphan-free but holed diagram.
  const std::vector<Site> sites = {{"big", 0, 0, 10}, {"small", 5, 0, 1}};
  const Diagram d = build_diagram(sites);
  ASSERT_EQ(d.faces.size(), 2u);
  int holes = 0;
  for (const Face& f : d.faces) {
    EXPECT_FALSE(f.orphan);
    if (f.site == 0) {
      EXPECT_FALSE(f.bounded);
      holes += static_cast<int>(face_cycles(d, f).size());
    } else {
      EXPECT_TRUE(f.bounded);
    }
  }
  EXPECT_EQ(holes, 1);
}

}  // namespace
}  // namespace covmap::voronoi

namespace covmap::voronoi {
namespace {

using covmap::testing::canonical_faces;

// Tracing by geometry alone (as for an input graph without sites) must find exactly the faces
// traced from the site labels: same boundary cycles, as sets of half-arcs.
class FacesByGeometry : public ::testing::TestWithParam<Family> {};

TEST_P(FacesByGeometry, MatchLabelledFaces) {
  for (int seed = 1; seed <= 10; ++seed) {
    const auto sites = testing::make_sites(GetParam(), 40, seed);
    const Diagram labelled = build_diagram(sites);
    Diagram geometric = labelled;
    for (Arc& a : geometric.arcs) a.left_site = a.right_site = kNone;
    trace_faces(geometric, FaceLabels::kGeometry);
    const auto a = canonical_faces(labelled), b = canonical_faces(geometric);
    ASSERT_EQ(a.size(), b.size()) << "seed " << seed;
    EXPECT_TRUE(a == b) << "seed " << seed;
  }
}

// Near-degenerate sites (a grid perturbed by 1e-9 relative) split each node of degree four into
// two nodes ~1e-9 apart joined by a tiny arc, where tracing by geometry can leave arc sides open
// and lose faces. Every near-degenerate family and perturbation must trace as the labels do.
TEST(FacesByGeometry, NearDegenerateSplitNodesMatchLabelledFaces) {
  using testing::NearBase;
  using testing::Perturbation;
  for (NearBase base : {NearBase::Grid, NearBase::Collinear, NearBase::Cocircular, NearBase::EqualWeight})
    for (Perturbation p : {Perturbation::Ulp, Perturbation::Rel1e15, Perturbation::Rel1e12, Perturbation::Rel1e9})
      for (double extent : {60.0, 1e4})
        for (int seed = 1; seed <= 4; ++seed) {
          const auto sites = testing::make_near_degenerate(base, p, 40, extent, seed);
          const Diagram labelled = build_diagram(sites);
          Diagram geometric = labelled;
          for (Arc& a : geometric.arcs) a.left_site = a.right_site = kNone;
          trace_faces(geometric, FaceLabels::kGeometry);
          EXPECT_TRUE(canonical_faces(labelled) == canonical_faces(geometric))
              << testing::near_base_name(base) << " " << testing::perturbation_name(p) << " extent " << extent
              << " seed " << seed;
        }
}

INSTANTIATE_TEST_SUITE_P(Families, FacesByGeometry,
                         ::testing::Values(Family::UniformWeights, Family::EqualWeights,
                                           Family::WeightClasses, Family::SharedMaximum,
                                           Family::Grid),
                         [](const auto& info) { return testing::family_name(info.param); });

}  // namespace
}  // namespace covmap::voronoi

namespace covmap::voronoi {
namespace {


// A graph large enough for the two-core paths of tracing by geometry (continuations node by node,
// the cycle walk split between workers, the hole-ray grid: 12 000 sites give ~36 000 arcs and a few
// hundred island circles). The faces must be the labelled ones, the face index must describe them,
// and a second tracing must give the same faces in the same order.
TEST(FacesByGeometryLarge, MatchLabelledFacesWithTheirIndex) {
  const auto sites = testing::make_sites(Family::UniformWeights, 12000, 3);
  const Diagram labelled = build_diagram(sites);
  Diagram geometric = labelled;
  for (Arc& a : geometric.arcs) a.left_site = a.right_site = kNone;
  FaceIndex index;
  trace_faces(geometric, FaceLabels::kGeometry, &index);
  std::size_t holes = 0;
  for (const Face& f : geometric.faces) holes += std::max<std::size_t>(face_cycles(geometric, f).size(), 1) - 1;
  EXPECT_GT(holes * geometric.arcs.size(), std::size_t{1} << 22) << holes << " holes: the hole-ray grid should be exercised";
  ASSERT_EQ(canonical_faces(labelled).size(), canonical_faces(geometric).size());
  EXPECT_TRUE(canonical_faces(labelled) == canonical_faces(geometric));

  ASSERT_EQ(index.face_of_half.size(), 2 * geometric.arcs.size());
  std::size_t on_cycles = 0;
  for (std::size_t f = 0; f < geometric.faces.size(); ++f)
    for (const auto cycle : face_cycles(geometric, f))
      for (std::size_t k = 0; k < cycle.size(); ++k) {
        const int h = 2 * cycle[k].arc + (cycle[k].forward ? 0 : 1);
        const HalfArc& n = cycle[(k + 1) % cycle.size()];
        EXPECT_EQ(index.face_of_half[h], static_cast<int>(f));
        EXPECT_EQ(index.next_half[h], 2 * n.arc + (n.forward ? 0 : 1));
        ++on_cycles;
      }
  EXPECT_EQ(on_cycles, index.face_of_half.size()) << "every half-arc bounds exactly one face";

  Diagram again = labelled;
  for (Arc& a : again.arcs) a.left_site = a.right_site = kNone;
  trace_faces(again, FaceLabels::kGeometry);
  ASSERT_EQ(again.faces.size(), geometric.faces.size());
  for (std::size_t f = 0; f < again.faces.size(); ++f) {
    ASSERT_EQ(face_cycles(again, f).size(), face_cycles(geometric, f).size()) << "face " << f;
    for (std::size_t b = 0; b < face_cycles(again, f).size(); ++b)
      for (std::size_t k = 0; k < face_cycles(again, f)[b].size(); ++k)
        ASSERT_EQ(face_cycles(again, f)[b][k].arc, face_cycles(geometric, f)[b][k].arc) << "face " << f;
  }
}


}  // namespace
}  // namespace covmap::voronoi

namespace covmap::voronoi {
namespace {

// Traced faces store their cycles face after face (each face's range starts where the previous
// one ends), and every half-arc of Diagram::half_arcs belongs to exactly one cycle.
TEST(FaceStorage, TracedFacesTileTheirCyclesAndHalfArcs) {
  for (int seed = 1; seed <= 5; ++seed) {
    const Diagram d = build_diagram(testing::make_sites(Family::UniformWeights, 40, seed));
    int next_cycle = 0;
    for (const Face& f : d.faces) {
      EXPECT_EQ(f.cycles_begin, next_cycle) << "seed " << seed;
      EXPECT_GE(f.cycles_end, f.cycles_begin);
      next_cycle = f.cycles_end;
    }
    EXPECT_EQ(next_cycle, static_cast<int>(d.cycles.size())) << "seed " << seed;
    std::vector<int> covered(d.half_arcs.size(), 0);
    for (const CycleRange& c : d.cycles) {
      ASSERT_TRUE(0 <= c.begin && c.begin < c.end && c.end <= static_cast<int>(d.half_arcs.size()));
      for (int k = c.begin; k < c.end; ++k) ++covered[k];
    }
    EXPECT_EQ(std::count(covered.begin(), covered.end(), 1), static_cast<std::ptrdiff_t>(covered.size())) << "seed " << seed;
  }
}

// Faces made by hand (add_face, add_cycle) read back as given.
TEST(FaceStorage, HandMadeFacesReadBack) {
  Diagram d;
  add_face(d, Face{0, true, false}, {{{3, true}, {4, false}}, {{5, true}}});
  add_face(d, Face{1, false, true});
  add_face(d, Face{2, false, false});
  add_cycle(d, std::vector<HalfArc>{{7, false}});
  ASSERT_EQ(d.faces.size(), 3u);
  EXPECT_EQ(d.faces[1].site, 1);
  EXPECT_TRUE(d.faces[1].orphan);
  ASSERT_EQ(face_cycles(d, 0).size(), 2u);
  EXPECT_EQ(face_cycles(d, 0)[0].size(), 2u);
  EXPECT_EQ(face_cycles(d, 0)[0][1].arc, 4);
  EXPECT_FALSE(face_cycles(d, 0)[0][1].forward);
  EXPECT_EQ(face_cycles(d, 0).back()[0].arc, 5);
  EXPECT_TRUE(face_cycles(d, 1).empty());
  ASSERT_EQ(face_cycles(d, 2).size(), 1u);
  EXPECT_EQ(face_cycles(d, 2).front()[0].arc, 7);
  int cycles = 0;
  for (const auto cycle : face_cycles(d, 0)) cycles += static_cast<int>(cycle.size());
  EXPECT_EQ(cycles, 3);
  clear_faces(d);
  EXPECT_TRUE(d.faces.empty() && d.cycles.empty() && d.half_arcs.empty());
}

}  // namespace
}  // namespace covmap::voronoi
