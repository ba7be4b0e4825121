// The coverage-map reader's second pass (io/coverage_map_cells.h) on several threads against one:
// the same cells, vertex count, distortion and problems, in the same order, for every worker count,
// and through the whole reader too.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "coverage_map_test_util.h"
#include "io/coverage_map_cells.h"
#include "io/coverage_map_drafts.h"
#include "io/local_projection.h"

namespace covmap::io {
namespace {

using detail::FeatureDrafts;
using detail::read_features_fast;
using detail::read_features_reference;
using testing::feature;
using testing::fingerprint;
using testing::OrderedJson;
using testing::outcome;
using testing::square;

constexpr const char* kFile = "map.geojson";

// A lon/lat map of n features in a grid, every seventh one broken in a way the second pass finds
// (a self-crossing ring, a ring of two vertices, a hole crossing its outer ring), so that cells,
// problems and the distortion all depend on every feature.
std::string grid_map(int n, bool broken = true) {
  OrderedJson features = OrderedJson::array();
  for (int i = 0; i < n; ++i) {
    const double x = 7.0 + 0.01 * (i % 40), y = 46.0 + 0.01 * (i / 40);
    OrderedJson rings = {square(x, y, 0.008)};
    if (!broken) {
      features.push_back(feature("s" + std::to_string(i), {{"type", "Polygon"}, {"coordinates", rings}}));
      continue;
    }
    if (i % 7 == 3) std::swap(rings[0][1], rings[0][2]);                                 // crosses itself
    if (i % 7 == 5) rings[0] = OrderedJson::array({{x, y}, {x + 0.001, y}, {x, y}});      // two vertices
    if (i % 7 == 6) rings.push_back(square(x + 0.004, y + 0.004, 0.008));                  // hole crossing out
    if (i % 5 == 1) rings.push_back(square(x + 0.002, y + 0.002, 0.002));                  // a proper hole
    features.push_back(feature("s" + std::to_string(i % 97), {{"type", "Polygon"}, {"coordinates", rings}}));
  }
  return OrderedJson{{"type", "FeatureCollection"}, {"features", features}}.dump();
}

std::string second_pass(const std::string& text, int workers) {
  FeatureDrafts first = read_features_reference(text, kFile, {});
  const LocalProjection local = LocalProjection::about(7.2, 46.1);
  CoverageMap map;
  detail::add_cells(first.drafts, &local, map, workers);
  std::string out = fingerprint(map);
  for (const auto& d : first.drafts)
    for (const auto& problem : d.problems) out += d.label + ": " + problem + "\n";
  return out;
}

TEST(CoverageMapCells, SameResultOnAnyNumberOfThreads) {
  const std::string text = grid_map(400);
  const std::string one = second_pass(text, 1);
  EXPECT_NE(one.find("crosses itself"), std::string::npos);
  EXPECT_NE(one.find("a ring needs at least 3"), std::string::npos);
  EXPECT_NE(one.find("crosses the outer ring"), std::string::npos);
  for (const int workers : {2, 3, 8}) EXPECT_EQ(second_pass(text, workers), one) << workers << " workers";
}

TEST(CoverageMapCells, WholeReaderSameOnAnyNumberOfThreads) {
  for (const bool broken : {false, true}) {
    const std::string text = grid_map(300, broken);
    const auto read = [&](int workers) {
      return outcome([&] { return detail::finish_coverage_map(*read_features_fast(text, {}), kFile, {}, workers); });
    };
    const std::string one = read(1);
    EXPECT_EQ(one.rfind("error: ", 0) == 0, broken);
    for (const int workers : {2, 5}) EXPECT_EQ(read(workers), one) << workers << " workers";
    EXPECT_EQ(outcome([&] { return parse_coverage_map(text, kFile); }), one);
  }
}

TEST(CoverageMapCells, SmallMapsStayOnTheCallingThread) { EXPECT_EQ(detail::cell_workers(100), 1); }

}  // namespace
}  // namespace covmap::io
