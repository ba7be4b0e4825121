// Multi-start refinement of audit(): the refinement from several starts (on maps small enough for
// it), the lowest cost winning, then restarts of sensors that escaped their own cells, then local
// re-solves of the sensors still in local minima (local_resolve.cpp).
#include <cmath>
#include <utility>

#include "audit/audit_stages.h"
#include "audit/tolerances.h"
#include "core/parallel.h"

namespace covmap::audit::stages {
namespace {

// A site lies in its own region. One that the refinement left inside another sensor's cell (or
// far outside the map) was dragged off by a poor start or a bad neighbour (and, with its weight,
// distorts the cells around it): it restarts from its cell's centroid with its neighbours'
// typical weight, and the refinement runs again (kRestartRounds times; a restart can free a
// neighbour that the escaped sensor held off, but another round costs a whole refinement).
Messages restart_escaped(const RefinementSetup& setup, const MapCells& cells, const MapRaster& raster,
                         fitting::RefineResult& refined) {
  Messages messages;
  const std::size_t n = setup.n;
  const std::vector<Point>& centroids = cells.centroids;
  for (int round = 0; round < tolerance::kRestartRounds; ++round) {
    std::vector<Site> repaired = refined.sites;
    std::vector<std::vector<double>> neighbour_logw(n);
    for (const auto& sample : setup.samples) {
      if (sample.site_b == kNone) continue;  // a range edge: no neighbour
      neighbour_logw[sample.site_a].push_back(std::log(refined.sites[sample.site_b].weight));
      neighbour_logw[sample.site_b].push_back(std::log(refined.sites[sample.site_a].weight));
    }
    int escaped = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const int at = raster.label_at(repaired[i].x, repaired[i].y);
      // Outside the map is possible for a sensor beyond its edge, but not far beyond.
      const bool placed = at == static_cast<int>(i) ||
                          (at == kNone && std::hypot(repaired[i].x - centroids[i].x, repaired[i].y - centroids[i].y) <= 3.0 * setup.spacing);
      // Neighbouring sensors' weights differ by modest factors; a weight that ran off to its bound
      // (e.g. 1e13 times its neighbours') is a divergence even where the position looks fine.
      const bool weight_ok = neighbour_logw[i].empty() ||
                             std::abs(std::log(repaired[i].weight) - median(neighbour_logw[i])) <= tolerance::kAuditMaxLogWeightJump;
      if (placed && weight_ok) continue;
      ++escaped;
      repaired[i].x = centroids[i].x, repaired[i].y = centroids[i].y;
      if (!neighbour_logw[i].empty()) repaired[i].weight = std::exp(median(neighbour_logw[i]));
    }
    if (escaped == 0) break;
    Refinement again = refine_from(setup, repaired, centroids);
    append(messages, again.messages);
    messages.push_back(std::to_string(escaped) + " sensor(s) ended outside their own cell (or with a weight far from their neighbours') and were refined again from their cell's centroid");
    if (!std::isfinite(again.refined.summary.final_cost)) break;
    refined = std::move(again.refined);
  }
  return messages;
}

}  // namespace

Refinement multi_start_refinement(const RefinementSetup& setup, const SiteEstimates& estimates,
                                  const std::vector<Site>& start, const MapCells& cells, const MapRaster& raster,
                                  const ReportedOf& reported_of,
                                  const std::function<void(const std::string& part)>& lap) {
  const auto lapped = [&lap](const std::string& part) {
    if (lap) lap(part);
  };
  const std::size_t n = setup.n;
  const std::vector<Point>& centroids = cells.centroids;
  const bool multi_start = n <= tolerance::kMultiStartSensors;
  // The first start: every sensor at its cell's centroid, with the tolerant weights. On generated
  // maps it converges faster than the junction positions (docs/ACCURACY.md), whose solution circles
  // come from short, noisy arcs; those positions are a second start on maps small enough for
  // several.
  std::vector<Site> centroid_start = estimates.sites;
  for (std::size_t i = 0; i < n; ++i) centroid_start[i].x = centroids[i].x, centroid_start[i].y = centroids[i].y;
  std::vector<std::vector<Site>> starts{centroid_start};
  // A second start from the tolerant estimates themselves (outside their own cell: centroid).
  if (multi_start) starts.push_back(start);
  std::size_t from_reported = 0;  // the index of the start from the reported sensors, if any
  if (multi_start && !reported_of.empty()) {
    from_reported = starts.size();
    // A further start from the reported sensors (where they exist): the lower cost wins.
    std::vector<Site> alt = start;
    for (auto [i, r] : reported_of) {
      alt[i].x = r->position.x, alt[i].y = r->position.y;
      if (r->weight) alt[i].weight = *r->weight;
    }
    starts.push_back(std::move(alt));
  }
  // The starts are independent refinements: on the refinement's threads, compared in start order.
  std::vector<Refinement> solved(starts.size());
  parallel_items(starts.size(), setup.options.threads,
                 [&](std::size_t k) { solved[k] = refine_from(setup, starts[k], centroids); });
  Refinement out;
  Messages& messages = out.messages;
  fitting::RefineResult& refined = out.refined;
  refined = std::move(solved[0].refined);
  for (std::size_t k = 0; k < starts.size(); ++k) {
    append(messages, solved[k].messages);
    const fitting::RefineResult& candidate = solved[k].refined;
    if (k == 0 || !(candidate.summary.final_cost < refined.summary.final_cost)) continue;
    if (k == from_reported)
      messages.push_back("refinement: the start from the reported sensors reached a lower cost (" +
                         std::to_string(candidate.summary.final_cost) + " < " + std::to_string(refined.summary.final_cost) + ")");
    refined = std::move(solved[k].refined);
  }
  lapped(multi_start ? "refinement (several starts)" : "refinement");
  append(messages, restart_escaped(setup, cells, raster, refined));
  lapped("refinement: restarts of escaped sensors");
  append(messages, resolve_misplaced(setup, estimates, cells, raster, reported_of, refined));
  lapped("refinement: local re-solves");
  // The re-solves moved sites: the residuals the model fit and the range-edge check read must be
  // those of the sites returned.
  if (refined.sample_residual.size() == setup.samples.size())
    refined.sample_residual = fitting::sample_residuals(refined.sites, setup.samples, refined.range);
  return out;
}

}  // namespace covmap::audit::stages
