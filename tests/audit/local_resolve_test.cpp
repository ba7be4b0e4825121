// The audit's local re-solves (audit/local_resolve.cpp) on a generated map whose truth is known
// (tools/mapgen): refinements left in local minima — one refinement from the tolerant estimates
// alone, and two neighbours merged at one point, the minimum that left sensors of a 10⁴-sensor map
// 10 bins off — are repaired: every sensor whose cell has at least 20 bins ends within 3 bins of
// the truth (docs/ACCURACY.md's target). Each test first asserts that the minimum is really there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "audit/audit_stages.h"
#include "tools/mapgen/coverage_map_generator.h"
#include "tools/mapgen/site_layouts.h"

namespace covmap::audit {
namespace {

using namespace stages;

constexpr double kBin = 100.0;

struct Pipeline {
  mapgen::CoverageMap generated;
  std::vector<CoverageCell> map;
  cleaning::CleanedMap cleaned;
  MapCells cells;
  MapRaster raster;
  SiteEstimates estimates;
  ReportedOf reported_of;  // none: the repair must not need reports
  RefinementSetup setup;
  fitting::RefineResult refined;
};

// 60 sensors, 2 km apart on average, 100 m bins, exact staircases, through the audit's stages up
// to a converged refinement.
void run_to_refinement(Pipeline& p, double weight_ratio = 3.0, unsigned seed = 7) {
  mapgen::RandomSitesOptions ro;
  ro.count = 60;
  ro.width_m = ro.height_m = 2000.0 * std::sqrt(60.0);
  ro.weight_ratio = weight_ratio;
  ro.seed = seed;
  mapgen::CoverageMapOptions o;
  o.bin_size_m = kBin;
  o.seed = seed;
  p.generated = mapgen::generate_coverage_map(mapgen::random_sites(ro), o);
  for (const mapgen::MapFeature& f : p.generated.features) {
    CoverageCell cell{p.generated.truth[f.sensor].id, static_cast<int>(p.map.size()), {}};
    for (const mapgen::MapCell& c : f.cells)
      cell.polygons.push_back({c.planar.front(), std::vector<Ring>(c.planar.begin() + 1, c.planar.end())});
    p.map.push_back(std::move(cell));
  }
  p.cleaned = cleaning::clean_coverage_map(p.map, AuditOptions{}.cleaning);
  p.cells = map_cells(p.map, p.cleaned);
  p.raster = map_raster(p.map, p.cells, kBin);
  p.estimates = estimate_sites(p.cleaned, p.cells.centroids);
  p.setup = refinement_setup(p.cleaned, p.cells.box, kBin, 1);
  const StartingSites start = starting_sites(p.estimates, p.cells, p.raster, p.reported_of);
  p.refined = refine_from(p.setup, start.sites, p.cells.centroids).refined;
}

// Per sensor with a cell of ≥ 20 bins, its distance from the truth in bins.
std::map<std::string, double> errors_in_bins(const Pipeline& p) {
  std::map<std::string, const mapgen::TrueSensor*> truth;
  for (const mapgen::TrueSensor& t : p.generated.truth) truth[t.id] = &t;
  std::map<std::string, double> out;
  for (const Site& s : p.refined.sites) {
    const mapgen::TrueSensor& t = *truth.at(s.id);
    if (t.bins >= 20) out[s.id] = std::hypot(s.x - t.position.x, s.y - t.position.y) / kBin;
  }
  return out;
}

// Per sensor with a cell of ≥ 20 bins, |log(ŵ / w)| after removing the median (the common factor
// of weights is free).
std::map<std::string, double> log_weight_errors(const Pipeline& p) {
  std::map<std::string, const mapgen::TrueSensor*> truth;
  for (const mapgen::TrueSensor& t : p.generated.truth) truth[t.id] = &t;
  std::vector<double> log_ratios;
  for (const Site& s : p.refined.sites) log_ratios.push_back(std::log(s.weight / truth.at(s.id)->weight));
  const double offset = median(log_ratios);
  std::map<std::string, double> out;
  for (const Site& s : p.refined.sites)
    if (truth.at(s.id)->bins >= 20) out[s.id] = std::abs(std::log(s.weight / truth.at(s.id)->weight) - offset);
  return out;
}

// Every sensor within 3 bins of its true position and, so that no weight ran off while positions
// look right, within a factor e^0.2 (3 dB at α = 3.5) of its true weight.
void expect_repaired(const Pipeline& p) {
  for (const auto& [id, e] : errors_in_bins(p)) EXPECT_LT(e, 3.0) << id;
  for (const auto& [id, e] : log_weight_errors(p)) EXPECT_LT(e, 0.2) << id;
}

double largest(const std::map<std::string, double>& errors) {
  double worst = 0.0;
  for (const auto& [id, e] : errors) worst = std::max(worst, e);
  return worst;
}

// One refinement from the tolerant estimates (without the audit's other starts, which hide it on
// maps this small) leaves a sensor of this map more than 3 bins off with every boundary near it
// fitted: a local minimum that the re-solve of its neighbourhood leaves.
TEST(LocalResolve, SingleStartLocalMinimumIsLeft) {
  Pipeline p;
  run_to_refinement(p);
  ASSERT_GT(largest(errors_in_bins(p)), 3.0) << "the refinement found the truth by itself: no regression to test";
  const Messages said = resolve_misplaced(p.setup, p.estimates, p.cells, p.raster, p.reported_of, p.refined);
  expect_repaired(p);
  // The re-solves are said once, for the report.
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find("solved again with their neighbourhoods"), std::string::npos) << said[0];
}

TEST(LocalResolve, MergedNeighboursAreSeparatedAgain) {
  Pipeline p;
  run_to_refinement(p);
  resolve_misplaced(p.setup, p.estimates, p.cells, p.raster, p.reported_of, p.refined);
  ASSERT_LT(largest(errors_in_bins(p)), 3.0) << "not repaired in the first place (SingleStartLocalMinimumIsLeft)";

  // Merge the sensor with the largest cell into its heaviest neighbour, as the refinement of the
  // 10⁴-sensor map did: at its neighbour's position (a hundredth of a bin aside) with its weight
  // (a part in 10⁷ less), then let the joint refinement settle from there.
  std::size_t a = 0;
  for (std::size_t i = 0; i < p.setup.n; ++i)
    if (p.cells.area[i] > p.cells.area[a]) a = i;
  int b = kNone;
  for (const fitting::BoundarySample& s : p.setup.samples) {
    const int other = s.site_a == static_cast<int>(a) ? s.site_b : s.site_b == static_cast<int>(a) ? s.site_a : kNone;
    if (other != kNone && (b == kNone || p.refined.sites[other].weight > p.refined.sites[b].weight)) b = other;
  }
  ASSERT_NE(b, kNone);
  std::vector<Site> merged = p.refined.sites;
  merged[a].x = merged[b].x + 0.01 * kBin;
  merged[a].y = merged[b].y;
  merged[a].weight = merged[b].weight * (1.0 - 1e-7);
  p.refined = refine_from(p.setup, merged, p.cells.centroids).refined;
  ASSERT_GT(largest(errors_in_bins(p)), 3.0) << "the joint refinement left the merged pair by itself: no regression";

  resolve_misplaced(p.setup, p.estimates, p.cells, p.raster, p.reported_of, p.refined);
  expect_repaired(p);
}

// An island's boundary is an Apollonius circle, which the island's and its host's sites fix only up
// to a family: the island anywhere inside, the host at its inverse point, their weight ratio the
// island's distance from the centre over the radius. A host that its other boundaries pin down is
// no suspect by itself (local_resolve.cpp, drop_pinned_island_hosts): moved with its island along
// that family by several bins, which leaves the circle as it was, the pair must still be found (by
// the host's misfit of its other boundaries, or the island's) and solved back to the truth.
TEST(LocalResolve, IslandHostMovedAlongItsIslandsCircleIsRepaired) {
  Pipeline p;
  run_to_refinement(p, 6.0, 11);
  resolve_misplaced(p.setup, p.estimates, p.cells, p.raster, p.reported_of, p.refined);
  ASSERT_LT(largest(errors_in_bins(p)), 3.0) << "not converged in the first place";
  std::vector<std::vector<int>> neighbours(p.setup.n);
  for (const fitting::BoundarySample& s : p.setup.samples) {
    if (s.site_b == kNone) continue;
    neighbours[s.site_a].push_back(s.site_b);
    neighbours[s.site_b].push_back(s.site_a);
  }
  int island = kNone, host = kNone;
  for (std::size_t j = 0; j < p.setup.n && island == kNone; ++j) {
    std::sort(neighbours[j].begin(), neighbours[j].end());
    neighbours[j].erase(std::unique(neighbours[j].begin(), neighbours[j].end()), neighbours[j].end());
    if (neighbours[j].size() == 1) island = static_cast<int>(j), host = neighbours[j][0];
  }
  ASSERT_NE(island, kNone) << "no island on this map: nothing to test";
  Site& in = p.refined.sites[island];
  Site& out = p.refined.sites[host];
  const double k = in.weight / out.weight;
  ASSERT_LT(k, 1.0);
  const Point c{(in.x - k * k * out.x) / (1 - k * k), (in.y - k * k * out.y) / (1 - k * k)};
  const double radius = k * std::hypot(in.x - out.x, in.y - out.y) / (1 - k * k);
  // The host 5 bins further from the centre, the island at its inverse point.
  const double from_centre = std::hypot(out.x - c.x, out.y - c.y), moved = from_centre + 5.0 * kBin;
  const Point unit{(out.x - c.x) / from_centre, (out.y - c.y) / from_centre};
  out.x = c.x + moved * unit.x, out.y = c.y + moved * unit.y;
  const double inverse = radius * radius / moved;
  in.x = c.x + inverse * unit.x, in.y = c.y + inverse * unit.y;
  in.weight = out.weight * radius / moved;
  // The circle is unchanged: a point on it stays equidistant in the weighted sense.
  const Point on{c.x + radius, c.y};
  EXPECT_NEAR(std::hypot(on.x - in.x, on.y - in.y) / in.weight, std::hypot(on.x - out.x, on.y - out.y) / out.weight,
              1e-9 * radius / in.weight);
  ASSERT_GT(largest(errors_in_bins(p)), 3.0) << "the move is not a regression to test";

  resolve_misplaced(p.setup, p.estimates, p.cells, p.raster, p.reported_of, p.refined);
  expect_repaired(p);
}

}  // namespace
}  // namespace covmap::audit
