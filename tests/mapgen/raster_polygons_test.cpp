#include "tools/mapgen/raster_polygons.h"

#include <gtest/gtest.h>

#include <random>

#include "core/point_in_polygon.h"
#include "io/polygon_check.h"
#include "mapgen_test_util.h"

namespace covmap::mapgen {
namespace {

using testing::components_per_label;
using testing::signed_area;

struct LabelRaster {
  std::string name;
  int nx = 0;
  int ny = 0;
  int label_count = 0;
  std::vector<int> labels;
};

std::vector<Point> to_points(const GridRing& ring) {
  std::vector<Point> out;
  for (const auto& v : ring) out.push_back({static_cast<double>(v.i), static_cast<double>(v.j)});
  return out;
}

// Every property of the contract, checked against independent computations.
void check_polygons(const LabelRaster& r, bool simplify) {
  std::string trace = r.name;
  trace += simplify ? " (simplified)" : " (every corner)";
  SCOPED_TRACE(trace);
  const auto polygons = raster_polygons(r.labels, r.nx, r.ny, simplify);

  std::vector<int> polygons_per_label(static_cast<std::size_t>(r.label_count), 0);
  std::vector<std::size_t> bins_per_label(static_cast<std::size_t>(r.label_count), 0);
  std::vector<std::vector<std::vector<Point>>> shapes;
  for (const auto& polygon : polygons) {
    ASSERT_GE(polygon.label, 0);
    ASSERT_LT(polygon.label, r.label_count);
    ++polygons_per_label[static_cast<std::size_t>(polygon.label)];
    bins_per_label[static_cast<std::size_t>(polygon.label)] += polygon.bins;
    ASSERT_FALSE(polygon.rings.empty());
    double area = 0.0;
    std::vector<std::vector<Point>> rings;
    for (std::size_t k = 0; k < polygon.rings.size(); ++k) {
      const GridRing& ring = polygon.rings[k];
      ASSERT_GE(ring.size(), 5u);
      EXPECT_EQ(ring.front(), ring.back()) << "ring not closed";
      std::vector<Point> points = to_points(ring);
      const double a = signed_area(points);
      if (k == 0) {
        EXPECT_GT(a, 0.0) << "outer ring must be counter-clockwise";
      } else {
        EXPECT_LT(a, 0.0) << "holes must be clockwise";
      }
      area += a;
      std::vector<Point> open(points.begin(), points.end() - 1);
      const auto defect = io::polygon_defect(open);
      EXPECT_FALSE(defect) << "ring " << k << " of a label-" << polygon.label << " polygon: " << *defect;
      const std::size_t n = open.size();
      for (std::size_t v = 0; v < n; ++v) {
        const Point a0 = open[(v + n - 1) % n], b0 = open[v], c0 = open[(v + 1) % n];
        const double cross = (b0.x - a0.x) * (c0.y - b0.y) - (b0.y - a0.y) * (c0.x - b0.x);
        const double length = std::abs(c0.x - b0.x) + std::abs(c0.y - b0.y);
        EXPECT_TRUE(b0.x == c0.x || b0.y == c0.y) << "edges follow bin sides";
        if (simplify) {
          EXPECT_NE(cross, 0.0) << "a collinear vertex survived simplification";
        } else {
          EXPECT_EQ(length, 1.0) << "without simplification every edge is one bin side";
        }
      }
      rings.push_back(std::move(points));
    }
    EXPECT_DOUBLE_EQ(area, static_cast<double>(polygon.bins)) << "area (outer minus holes) = bin count";
    shapes.push_back(std::move(rings));
  }
  EXPECT_EQ(polygons_per_label, components_per_label(r.labels, r.nx, r.ny, r.label_count));

  // Each bin centre lies in exactly the polygon of its own label, or in none when unlabelled.
  std::vector<std::size_t> expected_bins(static_cast<std::size_t>(r.label_count), 0);
  for (int j = 0; j < r.ny; ++j) {
    for (int i = 0; i < r.nx; ++i) {
      const int label = r.labels[static_cast<std::size_t>(j) * r.nx + i];
      if (label >= 0) ++expected_bins[static_cast<std::size_t>(label)];
      const Point centre{i + 0.5, j + 0.5};
      int hits = 0, hit_label = kNone;
      for (std::size_t p = 0; p < shapes.size(); ++p) {
        if (inside_rings(shapes[p], centre)) {
          ++hits;
          hit_label = polygons[p].label;
        }
      }
      ASSERT_EQ(hits, label >= 0 ? 1 : 0) << "bin (" << i << ", " << j << ")";
      if (label >= 0) {
        EXPECT_EQ(hit_label, label) << "bin (" << i << ", " << j << ")";
      }
    }
  }
  EXPECT_EQ(bins_per_label, expected_bins);
}

LabelRaster random_labels(int nx, int ny, int labels, double unlabelled, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  LabelRaster r{testing::numbered("random ", seed), nx, ny, labels, {}};
  for (int k = 0; k < nx * ny; ++k)
    r.labels.push_back(unit(rng) < unlabelled ? kNone : static_cast<int>(unit(rng) * labels));
  return r;
}

LabelRaster from_picture(const std::string& name, const std::vector<std::string>& rows) {
  // Rows top (north) to bottom; '.' is unlabelled, a digit is a label.
  LabelRaster r{name, static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), 10, {}};
  for (int j = r.ny - 1; j >= 0; --j)
    for (const char c : rows[static_cast<std::size_t>(j)]) r.labels.push_back(c == '.' ? kNone : c - '0');
  return r;
}

TEST(RasterPolygons, RandomLabelsWithSaddlesAndHoles) {
  // Independent random labels: many diagonal-only contacts (saddles), single-bin cells and holes.
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const auto r = random_labels(17 + static_cast<int>(seed), 23, 1 + static_cast<int>(seed % 4), 0.25, seed);
    check_polygons(r, true);
    check_polygons(r, false);
  }
}

TEST(RasterPolygons, HandDrawnCases) {
  const std::vector<LabelRaster> cases = {
      from_picture("checkerboard", {"0101", "1010", "0101"}),
      // One component (connected round the edge) whose two diagonal bins meet at a corner: the
      // hole on one side of that corner and the outer ring touch there.
      from_picture("pinch", {"00000", "0...0", "0.0.0", "00.00", "00000"}),
      from_picture("nested", {"0000000", "0111110", "0122210", "0120210", "0122210", "0111110", "0000000"}),
      from_picture("diagonal chain", {"1..", ".1.", "..1"}),
      from_picture("single bin", {"5"}),
      from_picture("two holes touching", {"00000", "0.0.0", "00.00", "00000"}),
  };
  for (const auto& r : cases) {
    check_polygons(r, true);
    check_polygons(r, false);
  }
}

TEST(RasterPolygons, PinchedComponentGetsAHoleTouchingTheOuterRing) {
  // Label 0 around a one-bin hole that touches the notch cut into the corner of the map diagonally:
  // the hole is still enclosed (4-connectivity), its ring touches the outer ring at one corner.
  const auto r = from_picture("pinch", {"000", "0.0", "00."});
  const auto polygons = raster_polygons(r.labels, r.nx, r.ny, true);
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].rings.size(), 2u);
  EXPECT_EQ(polygons[0].rings[1].size(), 5u) << "the hole is the single bin";
  const auto r2 = from_picture("enclosed", {"0000", "0.00", "00.0", "0000"});
  const auto p2 = raster_polygons(r2.labels, r2.nx, r2.ny, true);
  ASSERT_EQ(p2.size(), 1u);
  EXPECT_EQ(p2[0].rings.size(), 3u) << "two diagonal holes meeting at a corner stay two simple rings";
}

TEST(RasterPolygons, RejectsWrongSizes) {
  EXPECT_THROW(raster_polygons({0, 1, 2}, 2, 2, true), std::invalid_argument);
  EXPECT_THROW(raster_polygons({}, 0, 0, true), std::invalid_argument);
}

}  // namespace
}  // namespace covmap::mapgen
