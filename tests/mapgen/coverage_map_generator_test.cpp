#include "tools/mapgen/coverage_map_generator.h"

#include <GeographicLib/Geodesic.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "tools/mapgen/coverage_map_json.h"
#include "core/point_in_polygon.h"
#include "io/polygon_check.h"
#include "mapgen_test_util.h"

namespace covmap::mapgen {
namespace {

using testing::brute_force_owner;
using testing::random_test_sites;
using testing::signed_area;

std::vector<Site> as_sites(const CoverageMap& map) {
  std::vector<Site> sites;
  for (const auto& t : map.truth) sites.push_back(Site{t.id, t.position.x, t.position.y, t.weight});
  return sites;
}

double mean_spacing_brute_force(const std::vector<Site>& sites) {
  double sum = 0.0;
  for (const auto& a : sites) {
    double best = INFINITY;
    for (const auto& b : sites)
      if (&a != &b) best = std::min(best, std::hypot(a.x - b.x, a.y - b.y));
    sum += best;
  }
  return sum / static_cast<double>(sites.size());
}

// The contract's guarantees for an unjittered map, each against an independent computation.
void check_exact_map(const CoverageMap& map) {
  const RasterGrid& g = map.raster.grid;
  const auto sites = as_sites(map);
  const double range = map.options.max_range_m ? *map.options.max_range_m : -1.0;

  // Labels: brute force over all sites with the scaled weights.
  std::vector<std::size_t> bins(sites.size(), 0);
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const int expected = brute_force_owner(sites, g.x0 + (i + 0.5) * g.bin, g.y0 + (j + 0.5) * g.bin, range);
      ASSERT_EQ(map.raster.labels[g.index(i, j)], expected) << "bin (" << i << ", " << j << ")";
      if (expected != kNone) ++bins[static_cast<std::size_t>(expected)];
    }
  }

  // Polygons: closed, oriented, simple; area per sensor = bins × bin².
  std::vector<double> area(sites.size(), 0.0);
  std::vector<bool> has_feature(sites.size(), false);
  for (const auto& f : map.features) {
    ASSERT_GE(f.sensor, 0);
    has_feature[static_cast<std::size_t>(f.sensor)] = true;
    for (const auto& cell : f.cells) {
      ASSERT_EQ(cell.planar.size(), cell.output.size());
      for (std::size_t k = 0; k < cell.planar.size(); ++k) {
        const auto& ring = cell.planar[k];
        ASSERT_GE(ring.size(), 5u);
        EXPECT_EQ(ring.front().x, ring.back().x);
        EXPECT_EQ(ring.front().y, ring.back().y);
        const double a = signed_area(ring);
        EXPECT_TRUE(k == 0 ? a > 0.0 : a < 0.0) << "outer counter-clockwise, holes clockwise";
        area[static_cast<std::size_t>(f.sensor)] += a;
        const std::vector<Point> open(ring.begin(), ring.end() - 1);
        const auto defect = io::polygon_defect(open);
        EXPECT_FALSE(defect) << "sensor " << map.truth[static_cast<std::size_t>(f.sensor)].id << ": " << *defect;
      }
    }
  }
  for (std::size_t s = 0; s < sites.size(); ++s) {
    EXPECT_EQ(map.truth[s].bins, bins[s]);
    EXPECT_EQ(has_feature[s], bins[s] > 0);
    EXPECT_NEAR(area[s], static_cast<double>(bins[s]) * g.bin * g.bin, 1e-9 * g.bin * g.bin * static_cast<double>(g.bins()))
        << "sensor " << sites[s].id;
  }

  // No overlaps, no gaps: every bin centre lies in exactly its owner's polygon.
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const Point centre{g.x0 + (i + 0.5) * g.bin, g.y0 + (j + 0.5) * g.bin};
      int hits = 0, owner = kNone;
      for (const auto& f : map.features) {
        for (const auto& cell : f.cells) {
          if (inside_rings(cell.planar, centre)) {
            ++hits;
            owner = f.sensor;
          }
        }
      }
      const int label = map.raster.labels[g.index(i, j)];
      ASSERT_EQ(hits, label == kNone ? 0 : 1) << "bin (" << i << ", " << j << ")";
      ASSERT_EQ(owner, label);
    }
  }

  // Counts.
  const std::size_t covered = std::accumulate(bins.begin(), bins.end(), std::size_t{0});
  EXPECT_EQ(map.counts.covered_bins, covered);
  EXPECT_EQ(map.counts.bins, g.bins());
  EXPECT_EQ(map.counts.sensors_without_bins, static_cast<std::size_t>(std::count(bins.begin(), bins.end(), 0u)));
}

CoverageMapOptions planar_options() {
  CoverageMapOptions o;
  o.bin_size_m = 250.0;
  o.errors.position_sigma_m = 10.0;
  return o;
}

TEST(CoverageMap, PlanarMapMatchesBruteForceAndCoversEachBinOnce) {
  const auto sites = random_test_sites(40, 20'000.0, 5.0, 21);
  const CoverageMap map = generate_coverage_map(std::span<const Site>(sites), planar_options());
  check_exact_map(map);
  EXPECT_EQ(map.counts.covered_bins, map.counts.bins) << "no range: everything covered";
  // Corners are integers here: rounding to 2 decimals changes nothing.
  for (const auto& f : map.features)
    for (const auto& cell : f.cells)
      for (std::size_t k = 0; k < cell.planar.size(); ++k)
        for (std::size_t v = 0; v < cell.planar[k].size(); ++v) {
          EXPECT_EQ(cell.output[k][v].x, cell.planar[k][v].x);
          EXPECT_EQ(cell.output[k][v].y, cell.planar[k][v].y);
        }
}

TEST(CoverageMap, MaximumRangeLeavesIrregularUncoveredAreas) {
  const auto sites = random_test_sites(30, 20'000.0, 4.0, 5);
  CoverageMapOptions o = planar_options();
  o.max_range_m = 2'500.0;
  o.extent = Rectangle{-3000.0, -3000.0, 23'000.0, 23'000.0};
  const CoverageMap map = generate_coverage_map(std::span<const Site>(sites), o);
  check_exact_map(map);
  EXPECT_GT(map.counts.covered_bins, 0u);
  EXPECT_LT(map.counts.covered_bins, map.counts.bins);
}

TEST(CoverageMap, UnsimplifiedRingsHaveEveryCornerAndTheSameArea) {
  const auto sites = random_test_sites(12, 5'000.0, 3.0, 8);
  CoverageMapOptions o = planar_options();
  o.bin_size_m = 100.0;
  o.simplify_collinear = false;
  const CoverageMap full = generate_coverage_map(std::span<const Site>(sites), o);
  check_exact_map(full);
  o.simplify_collinear = true;
  const CoverageMap simple = generate_coverage_map(std::span<const Site>(sites), o);
  EXPECT_LT(simple.counts.vertices, full.counts.vertices);
  for (const auto& f : full.features)
    for (const auto& cell : f.cells)
      for (const auto& ring : cell.planar)
        for (std::size_t v = 0; v + 1 < ring.size(); ++v)
          EXPECT_DOUBLE_EQ(std::abs(ring[v + 1].x - ring[v].x) + std::abs(ring[v + 1].y - ring[v].y), 100.0);
}

TEST(CoverageMap, WeightsArePowersOfTheRadioModel) {
  const auto sites = random_test_sites(25, 10'000.0, 8.0, 2);
  CoverageMapOptions o = planar_options();
  o.alpha = 3.0;
  o.reference_power_dbm = 40.0;
  const CoverageMap map = generate_coverage_map(std::span<const Site>(sites), o);
  double wmax = 0.0;
  for (const auto& s : sites) wmax = std::max(wmax, s.weight);
  for (std::size_t k = 0; k < sites.size(); ++k) {
    EXPECT_DOUBLE_EQ(map.truth[k].weight, sites[k].weight / wmax);
    EXPECT_NEAR(map.truth[k].tx_power_dbm, 30.0 * std::log10(sites[k].weight / wmax) + 40.0, 1e-9);
    // Reported weight from reported power, the same law.
    const auto& r = map.reported[k];
    EXPECT_NEAR(30.0 * std::log10(r.weight) + 40.0, r.tx_power_dbm, 1e-9);
    EXPECT_NEAR(r.tx_power_dbm * 10.0, std::round(r.tx_power_dbm * 10.0), 1e-6) << "one decimal";
  }
}

TEST(CoverageMap, AutomaticExtentAndBinSize) {
  const auto sites = random_test_sites(50, 30'000.0, 2.0, 4);
  CoverageMapOptions o;
  o.extent_margin_spacings = 1.5;
  const CoverageMap map = generate_coverage_map(std::span<const Site>(sites), o);
  const double spacing = mean_spacing_brute_force(sites);
  EXPECT_EQ(*map.options.bin_size_m, default_bin_size(spacing));
  double xmin = INFINITY, ymin = INFINITY, xmax = -INFINITY, ymax = -INFINITY;
  for (const auto& s : sites) {
    xmin = std::min(xmin, s.x), ymin = std::min(ymin, s.y), xmax = std::max(xmax, s.x), ymax = std::max(ymax, s.y);
  }
  const double margin = 1.5 * spacing, bin = *map.options.bin_size_m;
  const RasterGrid& g = map.raster.grid;
  EXPECT_LE(g.x0, xmin - margin + 1e-6);
  EXPECT_GT(g.x0, xmin - margin - bin);
  EXPECT_LE(g.y0, ymin - margin + 1e-6);
  EXPECT_GT(g.y0, ymin - margin - bin);
  EXPECT_GE(g.x0 + g.nx * bin, xmax + margin - 1e-6);
  EXPECT_LT(g.x0 + g.nx * bin, xmax + margin + bin);
  EXPECT_GE(g.y0 + g.ny * bin, ymax + margin - 1e-6);
  EXPECT_LT(g.y0 + g.ny * bin, ymax + margin + bin);
  EXPECT_EQ(std::fmod(g.x0, bin), 0.0) << "bins aligned to multiples of their size";
}

TEST(CoverageMap, DefaultBinSizeIsOneTwentiethRoundedDownToOneTwoFive) {
  EXPECT_DOUBLE_EQ(default_bin_size(1000.0), 50.0);
  EXPECT_DOUBLE_EQ(default_bin_size(2100.0), 100.0);
  EXPECT_DOUBLE_EQ(default_bin_size(4100.0), 200.0);
  EXPECT_DOUBLE_EQ(default_bin_size(9999.0), 200.0);
  EXPECT_DOUBLE_EQ(default_bin_size(10'000.0), 500.0);
  EXPECT_DOUBLE_EQ(default_bin_size(30.0), 1.0);
}

std::vector<LonLatSite> bern_sites(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<LonLatSite> sites;
  for (int k = 0; k < n; ++k)
    sites.push_back({testing::numbered("b", k), 7.2 + 0.5 * unit(rng), 46.8 + 0.3 * unit(rng), 0.3 + unit(rng)});
  return sites;
}

TEST(CoverageMap, LonLatOutputProjectsBackWithinTheRounding) {
  const auto sites = bern_sites(30, 9);
  CoverageMapOptions o;
  o.frame = OutputFrame::kLonLat;
  o.bin_size_m = 400.0;
  o.centre = io::LonLat{7.45, 46.95};
  const CoverageMap map = generate_coverage_map(std::span<const LonLatSite>(sites), o);
  check_exact_map(map);
  ASSERT_TRUE(map.projection);
  const GeographicLib::Geodesic& wgs84 = GeographicLib::Geodesic::WGS84();
  // Half a unit in the 6th decimal: 0.056 m of latitude, 0.038 m of longitude here.
  const double rounding_m = 0.07;
  std::size_t checked = 0;
  for (const auto& f : map.features) {
    for (const auto& cell : f.cells) {
      for (std::size_t k = 0; k < cell.planar.size(); ++k) {
        for (std::size_t v = 0; v < cell.planar[k].size(); ++v) {
          const Point planar = cell.planar[k][v];
          const Point lonlat = cell.output[k][v];
          EXPECT_EQ(std::round(lonlat.x * 1e6) / 1e6, lonlat.x) << "6 decimals";
          const Point back = map.projection->forward(lonlat.x, lonlat.y);
          ASSERT_LE(std::hypot(back.x - planar.x, back.y - planar.y), rounding_m);
          // Independently of the projection code: geodesic distance from the centre equals the
          // planar distance up to the scale of transverse Mercator (< 3e-5 within 50 km), and
          // north/east go the right way.
          double s12 = 0.0;
          wgs84.Inverse(46.95, 7.45, lonlat.y, lonlat.x, s12);
          const double r = std::hypot(planar.x, planar.y);
          ASSERT_NEAR(s12, r, 3e-5 * r + rounding_m);
          if (std::abs(planar.y) > 10.0) {
            EXPECT_EQ(lonlat.y > 46.95, planar.y > 0.0);
          }
          if (std::abs(planar.x) > 10.0) {
            EXPECT_EQ(lonlat.x > 7.45, planar.x > 0.0);
          }
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 100u);
  // True sensors keep their given lon/lat; their plane positions are the projection of it.
  for (std::size_t k = 0; k < sites.size(); ++k) {
    ASSERT_TRUE(map.truth[k].lonlat);
    EXPECT_EQ(map.truth[k].lonlat->lon, sites[k].lon);
    EXPECT_EQ(map.truth[k].lonlat->lat, sites[k].lat);
    double s12 = 0.0;
    wgs84.Inverse(46.95, 7.45, sites[k].lat, sites[k].lon, s12);
    EXPECT_NEAR(s12, std::hypot(map.truth[k].position.x, map.truth[k].position.y), 3e-5 * s12 + 1e-3);
  }
}

TEST(CoverageMap, LonLatInputDefaultsToTheCentreOfItsBoundingBox) {
  const auto sites = bern_sites(10, 3);
  CoverageMapOptions o;
  o.frame = OutputFrame::kLonLat;
  const CoverageMap map = generate_coverage_map(std::span<const LonLatSite>(sites), o);
  double lo = 180, hi = -180, la = 90, ha = -90;
  for (const auto& s : sites) lo = std::min(lo, s.lon), hi = std::max(hi, s.lon), la = std::min(la, s.lat), ha = std::max(ha, s.lat);
  EXPECT_DOUBLE_EQ(map.projection->lon0(), 0.5 * (lo + hi));
  EXPECT_DOUBLE_EQ(map.projection->lat0(), 0.5 * (la + ha));
}

TEST(CoverageMap, LonLatOutputOfPlanarInputNeedsACentre) {
  const auto sites = random_test_sites(5, 1000.0, 2.0, 1);
  CoverageMapOptions o;
  o.frame = OutputFrame::kLonLat;
  EXPECT_THROW(generate_coverage_map(std::span<const Site>(sites), o), std::invalid_argument);
  o.centre = io::LonLat{8.0, 47.0};
  const CoverageMap map = generate_coverage_map(std::span<const Site>(sites), o);
  EXPECT_NEAR(map.features[0].cells[0].output[0][0].x, 8.0, 0.1);
}

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }
double stddev(const std::vector<double>& v) {
  const double m = mean(v);
  double sum = 0.0;
  for (const double x : v) sum += (x - m) * (x - m);
  return std::sqrt(sum / static_cast<double>(v.size() - 1));
}

TEST(CoverageMap, ReportedSensorsHaveTheRequestedErrors) {
  const auto sites = random_test_sites(2000, 100'000.0, 4.0, 13);
  CoverageMapOptions o;
  o.bin_size_m = 1000.0;
  o.errors.position_sigma_m = 15.0;
  o.errors.power_sigma_db = 1.5;
  o.errors.gross_fraction = 0.1;
  o.errors.gross_position_min_m = 500.0;
  o.errors.gross_position_max_m = 1500.0;
  o.errors.gross_power_min_db = 5.0;
  o.errors.gross_power_max_db = 10.0;
  o.coordinate_digits = 3;
  const CoverageMap map = generate_coverage_map(std::span<const Site>(sites), o);

  std::vector<double> dx, dy, dp, gross_distance;
  int position = 0, power = 0, both = 0, positive_power = 0;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const auto& t = map.truth[k];
    const auto& r = map.reported[k];
    // Measured from what is written, not from the recorded error terms.
    const double ex = r.output.x - t.position.x, ey = r.output.y - t.position.y;
    const double ep = r.tx_power_dbm - t.tx_power_dbm;
    switch (r.error.gross) {
      case GrossErrorKind::kNone:
        dx.push_back(ex), dy.push_back(ey), dp.push_back(ep);
        break;
      case GrossErrorKind::kPosition: ++position; break;
      case GrossErrorKind::kPower: ++power; break;
      case GrossErrorKind::kBoth: ++both; break;
    }
    if (r.error.gross == GrossErrorKind::kPosition || r.error.gross == GrossErrorKind::kBoth) {
      const double d = std::hypot(r.error.gross_offset.x, r.error.gross_offset.y);
      EXPECT_GE(d, 500.0);
      EXPECT_LE(d, 1500.0);
      gross_distance.push_back(d);
      // The written position is off by the gross offset plus small noise.
      EXPECT_NEAR(std::hypot(ex, ey), d, 6 * 15.0 * std::sqrt(2.0));
    } else {
      EXPECT_LT(std::hypot(ex, ey), 6 * 15.0 * std::sqrt(2.0));
    }
    if (r.error.gross == GrossErrorKind::kPower || r.error.gross == GrossErrorKind::kBoth) {
      EXPECT_GE(std::abs(r.error.gross_power_db), 5.0);
      EXPECT_LE(std::abs(r.error.gross_power_db), 10.0);
      EXPECT_NEAR(ep, r.error.gross_power_db, 6 * 1.5 + 0.05);
      positive_power += r.error.gross_power_db > 0 ? 1 : 0;
    } else {
      EXPECT_LT(std::abs(ep), 6 * 1.5 + 0.05);
    }
  }
  EXPECT_EQ(position + power + both, 200) << "round(0.1 × 2000)";
  EXPECT_EQ(map.counts.gross_errors, 200u);
  for (const int kind : {position, power, both}) {  // 200/3 ± 3.5 standard deviations
    EXPECT_GT(kind, 42);
    EXPECT_LT(kind, 91);
  }
  EXPECT_GT(positive_power, (power + both) / 4);
  EXPECT_LT(positive_power, 3 * (power + both) / 4);
  // 1800 samples: the standard deviation is known to ~1.7 %, the mean to sigma / 42.
  EXPECT_NEAR(stddev(dx), 15.0, 1.5);
  EXPECT_NEAR(stddev(dy), 15.0, 1.5);
  EXPECT_NEAR(mean(dx), 0.0, 15.0 * 5 / 42.0);
  EXPECT_NEAR(mean(dy), 0.0, 15.0 * 5 / 42.0);
  EXPECT_NEAR(stddev(dp), std::sqrt(1.5 * 1.5 + 0.01 / 12), 0.15);
  EXPECT_NEAR(mean(dp), 0.0, 1.5 * 5 / 42.0);
  EXPECT_NEAR(mean(gross_distance), 1000.0, 100.0) << "uniform in [500, 1500]";
}

TEST(CoverageMap, GrossErrorCountIsTheRoundedFraction) {
  EXPECT_EQ(gross_error_count(151, 0.1), 15u);
  EXPECT_EQ(gross_error_count(25, 0.1), 3u);  // 2.5 rounds up
  EXPECT_EQ(gross_error_count(24, 0.1), 2u);
  EXPECT_EQ(gross_error_count(7, 0.0), 0u);
  EXPECT_EQ(gross_error_count(7, 1.0), 7u);
  for (const int n : {1, 9, 25, 151}) {
    const auto sites = random_test_sites(n, 10'000.0, 2.0, static_cast<unsigned>(n));
    CoverageMapOptions o = planar_options();
    o.errors.gross_fraction = 0.1;
    o.extent = Rectangle{0, 0, 10'000, 10'000};
    o.bin_size_m = 500.0;
    const auto map = generate_coverage_map(std::span<const Site>(sites), o);
    EXPECT_EQ(map.counts.gross_errors, static_cast<std::size_t>(std::llround(0.1 * n))) << n;
  }
}

std::string all_text(const CoverageMap& map) {
  return feature_collection_text(map_geojson(map)) + feature_collection_text(sensors_geojson(map)) + truth_json(map).dump();
}

// Same seed, same bytes is checked across processes and builds by tests/mapgen/regenerate_test.sh
// (the bundled maps regenerate byte for byte); here: the seed really drives the randomness.
TEST(CoverageMap, AnotherSeedAnotherMap) {
  const auto sites = random_test_sites(30, 10'000.0, 3.0, 17);
  CoverageMapOptions o = planar_options();
  o.vertex_jitter_m = 2.0;
  o.errors.gross_fraction = 0.2;
  o.seed = 42;
  const std::string first = all_text(generate_coverage_map(std::span<const Site>(sites), o));
  o.seed = 43;
  EXPECT_NE(first, all_text(generate_coverage_map(std::span<const Site>(sites), o)));
}

TEST(CoverageMap, JitterMovesEveryVertexIndependently) {
  // Coarse bins (a cell is ~2 bins across) make thin parts of a cell meet at single corners.
  const auto sites = random_test_sites(60, 10'000.0, 10.0, 19);
  CoverageMapOptions o = planar_options();
  o.bin_size_m = 500.0;
  const CoverageMap exact = generate_coverage_map(std::span<const Site>(sites), o);
  o.vertex_jitter_m = 3.0;
  const CoverageMap noisy = generate_coverage_map(std::span<const Site>(sites), o);
  ASSERT_EQ(exact.features.size(), noisy.features.size());
  std::vector<double> moves;
  // grid corner -> its jittered copies, with the feature each came from
  std::map<std::pair<double, double>, std::vector<std::pair<std::size_t, Point>>> copies;
  for (std::size_t f = 0; f < exact.features.size(); ++f) {
    ASSERT_EQ(exact.features[f].cells.size(), noisy.features[f].cells.size());
    for (std::size_t c = 0; c < exact.features[f].cells.size(); ++c) {
      const auto& a = exact.features[f].cells[c].planar;
      const auto& b = noisy.features[f].cells[c].planar;
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t k = 0; k < a.size(); ++k) {
        ASSERT_EQ(a[k].size(), b[k].size());
        EXPECT_EQ(b[k].front().x, b[k].back().x) << "the closing vertex repeats the first exactly";
        for (std::size_t v = 0; v + 1 < a[k].size(); ++v) {
          moves.push_back(b[k][v].x - a[k][v].x);
          moves.push_back(b[k][v].y - a[k][v].y);
          copies[{a[k][v].x, a[k][v].y}].push_back({f, b[k][v]});
        }
      }
    }
  }
  EXPECT_NEAR(stddev(moves), 3.0, 0.3);
  int across = 0, within = 0;
  for (const auto& [corner, list] : copies) {
    for (std::size_t m = 0; m < list.size(); ++m) {
      for (std::size_t n = m + 1; n < list.size(); ++n) {
        const bool same = list[m].second.x == list[n].second.x && list[m].second.y == list[n].second.y;
        if (list[m].first == list[n].first) {
          ++within;
          EXPECT_TRUE(same) << "a corner shared by two rings of one sensor moves as one";
        } else {
          ++across;
          EXPECT_FALSE(same) << "neighbouring sensors get their own noise: small gaps and overlaps";
        }
      }
    }
  }
  EXPECT_GT(across, 10);
  EXPECT_GT(within, 0) << "the test needs a sensor whose rings touch";
}

TEST(CoverageMap, RejectsBadSensorsNamingThem) {
  std::vector<Site> sites = {{"a", 0, 0, 1}, {"b", 10, 0, -1}, {"a", 20, 0, 1}, {"c", 0, 0, 2}, {"d", NAN, 0, 1}};
  try {
    generate_coverage_map(std::span<const Site>(sites), planar_options());
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("4 problem(s)"), std::string::npos) << what;
    EXPECT_NE(what.find("site 1 ('b'): weight must be finite and positive (got -1)"), std::string::npos) << what;
    EXPECT_NE(what.find("site 2 ('a'): id already used by site 0"), std::string::npos) << what;
    EXPECT_NE(what.find("site 3 ('c'): same position as site 0 ('a')"), std::string::npos) << what;
    EXPECT_NE(what.find("site 4 ('d'): position must be finite"), std::string::npos) << what;
  }
  EXPECT_THROW(generate_coverage_map(std::span<const Site>(), planar_options()), std::invalid_argument);
  const std::vector<LonLatSite> bad = {{"x", 200.0, 10.0, 1.0}};
  EXPECT_THROW(generate_coverage_map(std::span<const LonLatSite>(bad), CoverageMapOptions{}), std::invalid_argument);
}

TEST(CoverageMap, OptionsAreValidated) {
  std::string why;
  EXPECT_TRUE(CoverageMapOptions{}.is_valid(&why)) << why;
  const auto invalid = [](auto change) {
    CoverageMapOptions o;
    change(o);
    std::string reason;
    return !o.is_valid(&reason) && !reason.empty();
  };
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.bin_size_m = 0.0; }));
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.extent = Rectangle{0, 0, 0, 1}; }));
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.max_range_m = -5.0; }));
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.coordinate_digits = 13; }));
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.vertex_jitter_m = NAN; }));
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.alpha = 0.0; }));
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.centre = io::LonLat{0.0, 90.0}; }));
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.errors.gross_fraction = 1.5; }));
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.errors.gross_position_min_m = 10, o.errors.gross_position_max_m = 5; }));
  EXPECT_TRUE(invalid([](CoverageMapOptions& o) { o.errors.power_sigma_db = -1; }));
  const auto sites = random_test_sites(5, 1000.0, 2.0, 1);
  CoverageMapOptions o;
  o.bin_size_m = -1.0;
  EXPECT_THROW(generate_coverage_map(std::span<const Site>(sites), o), std::invalid_argument);
}

TEST(CoverageMap, RefusesHugeRastersAndSingleSensorsWithoutExtent) {
  const auto sites = random_test_sites(5, 1000.0, 2.0, 1);
  CoverageMapOptions o;
  o.bin_size_m = 1.0;
  o.max_bins = 10'000;
  EXPECT_THROW(generate_coverage_map(std::span<const Site>(sites), o), std::invalid_argument);

  const std::vector<Site> one = {{"only", 5.0, 5.0, 2.0}};
  EXPECT_THROW(generate_coverage_map(std::span<const Site>(one), CoverageMapOptions{}), std::invalid_argument);
  CoverageMapOptions explicit_frame;
  explicit_frame.bin_size_m = 1.0;
  explicit_frame.extent = Rectangle{0, 0, 10, 10};
  explicit_frame.max_range_m = 4.0;
  const CoverageMap map = generate_coverage_map(std::span<const Site>(one), explicit_frame);
  check_exact_map(map);
  EXPECT_EQ(map.truth[0].weight, 1.0);
  EXPECT_EQ(map.features.size(), 1u);
  EXPECT_LT(map.counts.covered_bins, 100u);  // a disc of radius 4 inside 10 x 10
}

}  // namespace
}  // namespace covmap::mapgen
