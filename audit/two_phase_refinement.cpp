// One refinement of audit(): boundary samples and options shared by every refinement, weak priors,
// and a two-phase refinement from one set of starting values (fitting/refine.h).
#include <algorithm>
#include <cmath>
#include <map>

#include "audit/audit_stages.h"
#include "audit/boundary_samples.h"
#include "audit/tolerances.h"

namespace covmap::audit::stages {
namespace {

// Weak priors keep sites that the map barely constrains (one short boundary, a sliver) from
// drifting off while leaving every determined site to the data: a position prior of twice the
// mean sensor spacing about the start. (No prior on weights: it would also fix their common
// factor, which the boundaries leave free and every comparison removes; a weight's excursion
// is bounded in fitting/ instead.) A site whose posterior σ stays above half its prior σ is
// reported as undetermined.
// Phase 1 also holds every log weight loosely (±kAuditLogWeightPrior about its start): from a
// poor start a weakly bounded weight can otherwise run off and take a whole neighbourhood with
// it, and with weights held this way Ceres' inner iterations (per-site block descent) may run,
// which cut its iterations several-fold. Phase 2 drops the weight priors and polishes from
// phase 1's optimum (its gauge: one reference weight held), on every map, large ones included:
// phase 1's priors, loose for each weight, add up along the chains of neighbours of a large map,
// and its weights drift by about a dB RMS without phase 2, at little cost in time
// (docs/PERFORMANCE.md).
std::vector<fitting::SitePrior> priors_for(const RefinementSetup& setup, const std::vector<Site>& from, bool weights) {
  std::vector<fitting::SitePrior> priors;
  for (std::size_t i = 0; i < setup.n; ++i)
    priors.push_back({static_cast<int>(i), {from[i].x, from[i].y}, setup.prior_position_sigma,
                      std::log(from[i].weight), weights ? tolerance::kAuditLogWeightPrior : 0.0});
  return priors;
}

// Two sensors may not start at one point (their bisector would be undefined): a later one moves
// to its cell's centroid, or a tenth of a bin aside.
void separate(const RefinementSetup& setup, const std::vector<Point>& centroids, std::vector<Site>& sites) {
  std::map<std::pair<double, double>, int> taken;
  for (std::size_t i = 0; i < setup.n; ++i) {
    for (int attempt = 0; taken.count({sites[i].x, sites[i].y}); ++attempt) {
      if (attempt == 0) sites[i].x = centroids[i].x, sites[i].y = centroids[i].y;
      else sites[i].x += 0.1 * setup.bin_size_m * attempt;
    }
    taken[{sites[i].x, sites[i].y}] = static_cast<int>(i);
  }
}

}  // namespace

RefinementSetup refinement_setup(const cleaning::CleanedMap& cleaned, const Box& box, double bin_size_m, int threads) {
  RefinementSetup setup;
  const std::size_t n = cleaned.sensors.size();
  setup.n = n;
  setup.bin_size_m = bin_size_m;
  // Refinement on boundary samples (one per bin along each shared boundary).
  const double sigma = bin_size_m / std::sqrt(12.0);
  // One sample per bin; on maps too large for that to stay fast, one per two bins (each chain
  // still has about ten, against its curve's three parameters).
  const double sample_spacing = n > tolerance::kDenseSamplingSensors ? 2.0 * bin_size_m : bin_size_m;
  setup.samples = sample_boundaries(cleaned, sample_spacing, sigma);
  fitting::RefineOptions& ro = setup.options;
  ro.loss_scale = tolerance::kAuditLossScale;
  ro.threads = threads;
  ro.max_iterations = tolerance::kAuditMaxIterations;
  ro.function_tolerance = tolerance::kAuditFunctionTolerance;
  const double bw = box.xmax - box.xmin, bh = box.ymax - box.ymin;
  setup.spacing = std::sqrt(std::max(bw * bh, 1e-300) / static_cast<double>(std::max<std::size_t>(n, 1)));
  setup.prior_position_sigma = 2.0 * setup.spacing;
  return setup;
}

Refinement refine_from(const RefinementSetup& setup, std::vector<Site> from, const std::vector<Point>& centroids) {
  Refinement out;
  separate(setup, centroids, from);
  fitting::RefineOptions quick = setup.options;
  quick.compute_covariance = false;
  fitting::RefineOptions first = quick;
  first.inner_iterations = true;  // phase 1 has weight priors, no held reference: allowed
  first.function_tolerance = tolerance::kPhase1FunctionTolerance;
  quick.nonmonotonic_steps = true;
  // Phase 2 starts at phase 1's optimum and only releases the weights' priors: a few dozen
  // iterations settle it; its long tail (cost changes of parts in 10⁵, a few sensors creeping or
  // running off, which the restart round and the local re-solves then take up) is cut off by the
  // cap and, earlier, by the settle rule (audit/tolerances.h).
  quick.max_iterations = tolerance::kPhase2Iterations;
  quick.settle = fitting::SettleRule{tolerance::kPhase2SettleWindow, tolerance::kPhase2SettledBins * setup.bin_size_m,
                                     tolerance::kPhase2SettledLogWeight, tolerance::kPhase2MovingShare};
  try {
    fitting::RefineResult phase1 = fitting::refine_sites(from, setup.samples, priors_for(setup, from, true), first);
    out.messages.push_back("refinement phase 1: " + phase1.summary.brief());
    separate(setup, centroids, phase1.sites);
    out.refined = fitting::refine_sites(phase1.sites, setup.samples, priors_for(setup, from, false), quick);
    out.messages.push_back("refinement phase 2: " + out.refined.summary.brief());
    return out;
  } catch (const std::exception& e) {
    // A refinement that cannot run leaves the starting values, said in the report.
    out.messages.push_back(std::string("refinement failed (") + e.what() + "); kept the starting values");
    fitting::RefineResult& kept = out.refined;
    kept = {};
    kept.sites = from;
    double top = 0;
    for (const Site& site : kept.sites) top = std::max(top, site.weight);
    for (Site& site : kept.sites) site.weight /= top;
    kept.summary.final_cost = INFINITY;
    kept.summary.message = "not run";
    return out;
  }
}

}  // namespace covmap::audit::stages
