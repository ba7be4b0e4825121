#include "io/polygon_io.h"

#include <gtest/gtest.h>

#include <cmath>

#include "io/polygon_check.h"
#include "io_test_util.h"

namespace covmap::io {
namespace {

using testing::input_error_from;
using testing::TempDir;

double signed_area(const std::vector<Point>& ring) {
  double twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return twice / 2;
}

TEST(Orientation, ExactOnNearlyCollinearPoints) {
  // Points a few ulps off the line y = x: the naive determinant gets many of these wrong
  // (Shewchuk's classic example); the exact answer is the sign of (py - px).
  const double ulp = std::ldexp(1.0, -53);
  int wrong_naive = 0;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const Point p{0.5 + i * ulp, 0.5 + j * ulp}, q{12, 12}, r{24, 24};
      const int expected = (j > i) - (j < i);
      ASSERT_EQ(orientation(p, q, r), expected) << i << "," << j;
      const double naive = (p.x - r.x) * (q.y - r.y) - (p.y - r.y) * (q.x - r.x);
      wrong_naive += ((naive > 0) - (naive < 0)) != expected;
    }
  }
  EXPECT_GT(wrong_naive, 0) << "the test no longer exercises the exact fallback";
}

TEST(PolygonDefect, ReportsEachKind) {
  EXPECT_EQ(polygon_defect(std::vector<Point>{{0, 0}, {1, 0}}).value(), "a polygon needs at least 3 vertices (got 2)");
  EXPECT_NE(polygon_defect(std::vector<Point>{{0, 0}, {1, 0}, {NAN, 1}})->find("not finite"), std::string::npos);
  EXPECT_NE(polygon_defect(std::vector<Point>{{0, 0}, {1, 0}, {1, 0}, {0, 1}})->find("repeats"), std::string::npos);
  EXPECT_NE(polygon_defect(std::vector<Point>{{0, 0}, {1, 1}, {3, 3}})->find("zero area"), std::string::npos);
  // Bow tie.
  EXPECT_NE(polygon_defect(std::vector<Point>{{0, 0}, {2, 2}, {2, 0}, {0, 2}})->find("not simple"), std::string::npos);
  // A vertex touching a non-adjacent edge.
  EXPECT_NE(polygon_defect(std::vector<Point>{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}})->find("not simple"), std::string::npos);
  // Doubling back along an edge.
  EXPECT_NE(polygon_defect(std::vector<Point>{{0, 0}, {4, 0}, {2, 0}, {2, 3}})->find("overlap"), std::string::npos);
  EXPECT_FALSE(polygon_defect(std::vector<Point>{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}));  // concave is fine
}

TEST(ParseClip, RectangleIsCounterClockwise) {
  const auto r = parse_clip(" 0 , -1 ,10,+5 ");
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0].x, 0);
  EXPECT_EQ(r[0].y, -1);
  EXPECT_EQ(r[2].x, 10);
  EXPECT_EQ(r[2].y, 5);
  EXPECT_GT(signed_area(r), 0);
}

TEST(ParseClip, BadRectangles) {
  EXPECT_STREQ(input_error_from([] { parse_clip("10,0,0,5"); }).what(),
               "clip rectangle '10,0,0,5': expected xmin,ymin,xmax,ymax with xmin < xmax and ymin < ymax");
  EXPECT_STREQ(input_error_from([] { parse_clip("1,2,3"); }).what(),
               "clip rectangle '1,2,3': expected four numbers xmin,ymin,xmax,ymax");
  EXPECT_NE(input_error_from([] { parse_clip("0,0,inf,1"); }).message().find("finite"), std::string::npos);
  EXPECT_NE(input_error_from([] { parse_clip("/no/such/clip.json"); }).message().find("cannot open"), std::string::npos);
}

TEST(ParseClip, PolygonFileClockwiseIsReversedAndClosingVertexDropped) {
  TempDir dir;
  const auto file = dir.write("p.json", R"({"format":"covmap.polygon/1","points":[[0,0],[0,3],[2,3],[4,0],[0,0]]})");
  const auto p = parse_clip(file.string());
  ASSERT_EQ(p.size(), 4u);
  EXPECT_GT(signed_area(p), 0);
  EXPECT_DOUBLE_EQ(signed_area(p), 9);
}

TEST(ParseClip, SelfIntersectingPolygonIsRejected) {
  TempDir dir;
  const auto file = dir.write("bow.json", R"({"format":"covmap.polygon/1","points":[[0,0],[2,2],[2,0],[0,2]]})");
  const auto e = input_error_from([&] { parse_clip(file.string()); });
  EXPECT_EQ(e.file, file.string());
  EXPECT_EQ(e.item(), "points");
  EXPECT_NE(e.message().find("not simple"), std::string::npos) << e.what();
}

TEST(ParseClip, PolygonFileErrors) {
  TempDir dir;
  const auto message = [&](const std::string& text) {
    return std::string(input_error_from([&] { parse_clip(dir.write("p.json", text).string()); }).what());
  };
  const std::string p = (dir / "p.json").string();
  EXPECT_EQ(message(R"({"format":"covmap.polygon/1","points":[[0,0],[1,0],["1",1]]})"),
            p + ": points[2][0]: must be a number (got string \"1\")");
  EXPECT_EQ(message(R"({"format":"covmap.polygon/1","points":[[0,0],[1,0]]})"),
            p + ": points: a polygon needs at least 3 vertices (got 2)");
  EXPECT_EQ(message(R"({"format":"covmap.polygon/2","points":[]})"),
            p + ": format: expected \"covmap.polygon/1\" (got string \"covmap.polygon/2\")");
  EXPECT_NE(message(R"({"points":[]})").find("expected {\"format\":\"covmap.polygon/1\""), std::string::npos);
  EXPECT_NE(message("[1,2").find("invalid JSON"), std::string::npos);
}

TEST(ParseClip, GeoJson) {
  TempDir dir;
  const std::string ring = "[[0,0,100],[4,0,100],[4,4,100],[0,4,100],[0,0,100]]";
  const auto polygon = dir.write("a.geojson", R"({"type":"Polygon","coordinates":[)" + ring + "]}");
  const auto feature = dir.write("b.geojson", R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[)" + ring + "]}}");
  const auto collection = dir.write("c.geojson", R"({"type":"FeatureCollection","features":[{"type":"Feature","geometry":{"type":"Polygon","coordinates":[)" + ring + "]}}]}");
  for (const auto& file : {polygon, feature, collection}) {
    const auto p = parse_clip(file.string());
    EXPECT_EQ(p.size(), 4u) << file;
    EXPECT_DOUBLE_EQ(signed_area(p), 16) << file;
  }
}

TEST(ParseClip, GeoJsonErrors) {
  TempDir dir;
  const auto item = [&](const std::string& text) {
    return input_error_from([&] { parse_clip(dir.write("g.geojson", text).string()); }).item();
  };
  EXPECT_EQ(item(R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,0]],[[1,1],[2,1],[2,2],[1,1]]]})"), "coordinates");
  EXPECT_EQ(item(R"({"type":"MultiPolygon","coordinates":[]})"), "type");
  EXPECT_EQ(item(R"({"type":"Feature","geometry":{"type":"Point","coordinates":[0,0]}})"), "geometry.type");
  EXPECT_EQ(item(R"({"type":"FeatureCollection","features":[]})"), "features");
  EXPECT_EQ(item(R"({"type":"Polygon","coordinates":[[[0,0],[2,2],[2,0],[0,2],[0,0]]]})"), "coordinates[0]");
}

}  // namespace
}  // namespace covmap::io
