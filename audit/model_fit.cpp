#include "audit/model_fit.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <limits>

#include "audit/tolerances.h"

namespace covmap::audit::stages {
namespace {

// The free fit's mean square of each sample's chain (map chains, then range-edge pieces in the
// order boundary_samples.cpp numbers them), floored at the map's own resolution.
std::vector<double> free_mean_squares(const cleaning::CleanedMap& cleaned, double floor_ms) {
  std::vector<double> ms;
  for (const cleaning::BoundaryChain& chain : cleaned.chains) ms.push_back(std::max(chain.fit.rms * chain.fit.rms, floor_ms));
  for (const cleaning::RangeEdge& edge : cleaned.range_edges)
    for (std::size_t k = 0; k < edge.pieces.size(); ++k) ms.push_back(std::max(edge.fit.rms * edge.fit.rms, floor_ms));
  return ms;
}

std::string readable_ratio(double r) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, r < 10 ? "%.1f" : "%.0f", r);
  return buffer;
}

}  // namespace

ModelFitResult model_fit(const cleaning::CleanedMap& cleaned, std::span<const fitting::BoundarySample> samples,
                         std::span<const double> residuals, std::span<const double> sensor_area, double bin,
                         const AuditOptions& options) {
  const std::size_t n = cleaned.sensors.size();
  ModelFitResult out;
  out.sensor_ratio.assign(n, std::numeric_limits<double>::quiet_NaN());
  if (residuals.size() != samples.size() || samples.empty()) return out;
  const double floor = tolerance::kMisfitNoiseFloorBins * bin;
  const std::vector<double> free_ms = free_mean_squares(cleaned, floor * floor);
  std::vector<double> model_sum(n, 0.0), free_sum(n, 0.0);
  std::vector<int> count(n, 0);
  double model_total = 0.0, free_total = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const fitting::BoundarySample& s = samples[k];
    if (s.chain < 0 || static_cast<std::size_t>(s.chain) >= free_ms.size() || !std::isfinite(residuals[k])) continue;
    const double r2 = residuals[k] * residuals[k], f = free_ms[static_cast<std::size_t>(s.chain)];
    model_total += r2, free_total += f;
    for (int site : {s.site_a, s.site_b}) {
      if (site == kNone) continue;
      model_sum[site] += r2;
      free_sum[site] += f;
      ++count[site];
    }
  }
  ModelFit& fit = out.map;
  fit.known = free_total > 0;
  fit.ratio = fit.known ? model_total / free_total : 0.0;
  double area = 0.0, misfit_area = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = i < sensor_area.size() ? std::abs(sensor_area[i]) : 0.0;
    area += a;
    // A boundary of a few bins is below the map's resolution: its ratio says nothing.
    if (!(free_sum[i] > 0) || count[i] < tolerance::kMisfitMinSamples ||
        a < tolerance::kResolvedCellBins * bin * bin)
      continue;
    out.sensor_ratio[i] = model_sum[i] / free_sum[i];
    if (out.sensor_ratio[i] > options.model_misfit_ratio) ++fit.misfit_sensors, misfit_area += a;
  }
  fit.misfit_area_share = area > 0 ? misfit_area / area : 0.0;
  fit.misfit = fit.known && (fit.ratio > options.model_misfit_ratio || fit.misfit_area_share > tolerance::kMisfitAreaShare);
  return out;
}

void apply_model_fit(const ModelFitResult& fit, const AuditOptions& options, std::vector<SensorAudit>& sensors) {
  for (std::size_t i = 0; i < fit.sensor_ratio.size() && i < sensors.size(); ++i) {
    const double ratio = fit.sensor_ratio[i];
    if (!std::isfinite(ratio)) continue;
    SensorAudit& s = sensors[i];
    s.model_fit_ratio = ratio;
    if (!(ratio > options.model_misfit_ratio) || !s.reported) continue;
    s.verdict = SensorVerdict::kModelMisfit;
    s.basis = VerdictBasis::kModelFit;
    s.chi2 = {};  // not judged
    s.reason = "the map around this sensor does not follow the path-loss model: the model draws its boundaries " +
               readable_ratio(ratio) + " times worse (mean square) than free curves do, above the threshold " +
               readable_ratio(options.model_misfit_ratio) + "; not judged";
  }
}

}  // namespace covmap::audit::stages
