// audit(): the driver over its stages (audit_stages.h names them and the files that hold them).
#include "audit/audit.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string_view>
#include <unordered_set>

#include "audit/alpha_estimate.h"
#include "audit/audit_stages.h"
#include "audit/model_fit.h"
#include "audit/start_values.h"
#include "audit/tolerances.h"
#include "fitting/local_uncertainty.h"

namespace covmap::audit {
namespace {

using namespace stages;

// Appends {what, seconds since the previous lap} to the audit's timings (apart from its messages,
// which must read the same on every run).
class StageTimer {
 public:
  StageTimer(std::chrono::steady_clock::time_point start, std::vector<StageTiming>& timings)
      : last_(start), timings_(timings) {}
  void lap(const std::string& what) {
    const auto now = std::chrono::steady_clock::now();
    timings_.push_back({what, std::chrono::duration<double>(now - last_).count()});
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_;
  std::vector<StageTiming>& timings_;
};

// kMaxSensors, checked before any work.
void refuse_oversized(std::span<const CoverageCell> map) {
  std::unordered_set<std::string_view> sensors;
  for (const CoverageCell& cell : map) sensors.insert(cell.sensor);
  if (sensors.size() > kMaxSensors)
    throw MapTooLarge("the map names " + std::to_string(sensors.size()) + " sensors; one audit takes at most " +
                                std::to_string(kMaxSensors) +
                                " (the refinement would run for hours): split the map into regions");
}

// R of the refinement, with the sensitivity it implies when powers fix the scale.
std::optional<ReceptionLimit> reception_limit(const cleaning::CleanedMap& cleaned, const fitting::RefineResult& refined,
                                              std::span<const fitting::BoundarySample> samples,
                                              const WeightScale& scale, const AuditOptions& options) {
  if (!refined.range) return std::nullopt;
  ReceptionLimit limit;
  limit.range_m = *refined.range;
  limit.range_sigma_m = refined.range_sigma > 0 ? refined.range_sigma
                                                : fitting::range_sigma(refined.sites, samples);
  limit.sensors = cleaned.range_edges.size();
  if (scale.p0 && options.alpha) limit.sensitivity_dbm = *scale.p0 - 10.0 * *options.alpha * std::log10(limit.range_m);
  return limit;
}

}  // namespace

AuditResult audit(std::span<const CoverageCell> map, std::span<const ReportedSensor> reported,
                  const AuditOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (map.empty()) throw std::invalid_argument("audit: the map has no cells");
  refuse_oversized(map);
  auto progress = [&](const std::string& stage, double f) {
    if (options.progress) options.progress(stage, f);
  };
  AuditResult out;

  // 1. Clean the map into chains, junctions and fitted bisectors.
  progress("cleaning", 0.0);
  cleaning::CleaningOptions cleaning_options = options.cleaning;
  cleaning_options.threads = options.threads;
  out.cleaned = cleaning::clean_coverage_map(map, cleaning_options);
  const cleaning::CleanedMap& cleaned = out.cleaned;
  const MapCells cells = map_cells(map, cleaned);
  out.bin_size_m = bin_size(cleaned, cells.box);

  // 2. Starting values: tolerant recognition; reported values where it found nothing better.
  progress("recognition", 0.2);
  const SiteEstimates estimates = estimate_sites(cleaned, cells.centroids, options.threads);
  const ReportedOf reported_of = reported_in_map(reported, cells);
  const MapRaster raster = map_raster(map, cells, out.bin_size_m);
  const StartingSites start = starting_sites(estimates, cells, raster, reported_of);
  append(out.messages, start.messages);

  // 3. Refinement on boundary samples (one per bin along each shared boundary), from several starts.
  progress("refinement", 0.3);
  RefinementSetup setup = refinement_setup(cleaned, cells.box, out.bin_size_m, options.threads);
  auto last_beat = std::chrono::steady_clock::now();
  setup.options.on_iteration = [&](int iteration) {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_beat).count() < tolerance::kHeartbeatSeconds) return;
    last_beat = now;
    progress("refinement, solver iteration " + std::to_string(iteration), 0.3);
  };
  out.boundary_samples = setup.samples.size();
  StageTimer timer(t0, out.timings);
  timer.lap("cleaning and starting values");
  Refinement refinement = multi_start_refinement(setup, estimates, start.sites, cells, raster, reported_of,
                                                 [&](const std::string& part) { timer.lap(part); });
  append(out.messages, refinement.messages);
  fitting::RefineResult& refined = refinement.refined;
  append(out.messages, check_range_edges(setup, refined, cells, options, out.cleaned));
  out.boundary_samples = setup.samples.size();
  out.refinement_summary = refined.summary.brief();
  out.refinement_converged = refined.summary.converged;
  progress("verification", 0.7);

  // 4. Powers and the common factor of weights; 5. per sensor: reconstruction, uncertainty, verdict.
  const WeightScale scale = weight_scale(refined, reported_of, options);
  out.reception = reception_limit(out.cleaned, refined, setup.samples, scale, options);
  const VerificationInputs verification{.cleaned = cleaned, .cells = cells, .raster = raster, .setup = setup,
                                        .refined = refined, .reported_of = reported_of, .reported = reported,
                                        .scale = scale, .options = options};
  out.sensors = sensor_audits(verification);
  const ModelFitResult fit = model_fit(cleaned, setup.samples, refined.sample_residual, cells.area, out.bin_size_m, options);
  out.model_fit = fit.map;
  apply_model_fit(fit, options, out.sensors);
  apply_report_fit(setup.samples, cells.area, options, out.model_fit, out.sensors);
  out.alpha_estimate = estimate_alpha(out.sensors, options.alpha);
  // 6. Recompute the diagrams and compare them with the map on a raster.
  append(out.messages, recomputed_diagrams(verification, out));
  timer.lap("recomputed diagrams and comparison");
  progress("done", 1.0);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace covmap::audit
