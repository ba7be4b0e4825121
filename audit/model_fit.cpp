#include "audit/model_fit.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <cstdio>
#include <string>
#include <limits>

#include "audit/audit_stages.h"
#include "audit/tolerances.h"
#include "audit/verdict.h"

namespace covmap::audit::stages {
namespace {

// The free fit's mean square behind each sample, floored at the map's own resolution: its chain's
// fit for a boundary sample, its sensor's range circle for a range-edge sample (looked up by
// sensor, so that dropping a sensor's range edge renumbers nothing).
class FreeMeanSquares {
 public:
  FreeMeanSquares(const cleaning::CleanedMap& cleaned, double floor_ms)
      : range_(cleaned.sensors.size(), std::numeric_limits<double>::quiet_NaN()) {
    for (const cleaning::BoundaryChain& chain : cleaned.chains) chain_.push_back(std::max(chain.fit.rms * chain.fit.rms, floor_ms));
    for (const cleaning::RangeEdge& edge : cleaned.range_edges)
      range_[static_cast<std::size_t>(edge.sensor)] = std::max(edge.fit.rms * edge.fit.rms, floor_ms);
  }
  // NaN when unknown (no such chain, or the sensor has no range edge).
  double of(const fitting::BoundarySample& s) const {
    if (s.site_b == kNone) return range_[static_cast<std::size_t>(s.site_a)];
    return s.chain >= 0 && static_cast<std::size_t>(s.chain) < chain_.size() ? chain_[static_cast<std::size_t>(s.chain)]
                                                                               : std::numeric_limits<double>::quiet_NaN();
  }

 private:
  std::vector<double> chain_, range_;
};

std::string readable_probability(double p) {
  char buffer[32];
  if (p < 0.001) return "below 0.001";
  std::snprintf(buffer, sizeof buffer, "%.3f", p);
  return buffer;
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
  const FreeMeanSquares free_ms(cleaned, floor * floor);
  std::vector<double> model_sum(n, 0.0), free_sum(n, 0.0);
  std::vector<int> count(n, 0);
  double model_total = 0.0, free_total = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const fitting::BoundarySample& s = samples[k];
    const double f = free_ms.of(s);
    if (!std::isfinite(f) || !std::isfinite(residuals[k])) continue;
    const double r2 = residuals[k] * residuals[k];
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
  // The decision rests on the share of area, not on the pooled ratio, which a few sensors can
  // dominate (a mean square is not robust).
  fit.misfit = fit.known && fit.misfit_area_share > tolerance::kMisfitAreaShare;
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
    s.chi2 = {};  // χ² is set exactly for verdicts of the boundary fit (audit.h)
    s.reason = "the map around this sensor does not follow the path-loss model: the model draws its boundaries " +
               readable_ratio(ratio) + " times worse (mean square) than free curves do, above the threshold " +
               readable_ratio(options.model_misfit_ratio) + "; not judged";
  }
}

namespace {

// The χ² tail probability of a sensor the boundary fit judged (NaN otherwise).
double tail_probability(const SensorAudit& s) {
  if (s.basis != VerdictBasis::kBoundaryFit || !s.chi2) return std::numeric_limits<double>::quiet_NaN();
  return chi2_tail(*s.chi2, s.weight_ratio ? 3 : 2);
}

}  // namespace

void apply_report_fit(std::span<const fitting::BoundarySample> samples, std::span<const double> sensor_area,
                      const AuditOptions& options, ModelFit& fit, std::vector<SensorAudit>& sensors) {
  const std::size_t n = sensor_area.size();
  std::vector<double> p(n);
  std::vector<double> judged;
  for (std::size_t i = 0; i < n && i < sensors.size(); ++i) {
    p[i] = tail_probability(sensors[i]);
    if (std::isfinite(p[i])) judged.push_back(p[i]);
  }
  if (judged.size() >= tolerance::kMisfitMinJudged) fit.reports_median_p = median(judged);
  std::vector<std::set<int>> neighbours(n);
  for (const fitting::BoundarySample& s : samples)
    if (s.site_b != kNone) neighbours[s.site_a].insert(s.site_b), neighbours[s.site_b].insert(s.site_a);
  std::vector<std::pair<std::size_t, double>> misfits;  // decided on the verdicts before any change
  for (std::size_t i = 0; i < n && i < sensors.size(); ++i) {
    if (!std::isfinite(p[i])) continue;
    std::vector<double> around;
    for (int k : neighbours[i])
      if (std::isfinite(p[k])) around.push_back(p[k]);
    if (around.size() < tolerance::kMisfitMinNeighbours) continue;
    if (const double m = median(around); m < tolerance::kMisfitPValue) misfits.push_back({i, m});
  }
  for (auto [i, m] : misfits) {
    SensorAudit& s = sensors[i];
    s.verdict = SensorVerdict::kModelMisfit;
    s.basis = VerdictBasis::kModelFit;
    s.chi2 = {};  // χ² is set exactly for verdicts of the boundary fit (audit.h)
    s.reason = "the reports around this sensor do not follow the path-loss model: its neighbours' reports " +
               std::string("disagree with the map (median χ² tail probability ") + readable_probability(m) +
               ", below " + readable_probability(tolerance::kMisfitPValue) + "), so its own disagreement (" +
               s.reason + ") is not blamed on it; not judged";
  }
  // The map-level decision rests on the boundaries' share (apply_model_fit) and the map-wide median;
  // the neighbourhood markings above are local by design (on a small map with many gross errors a
  // few neighbourhoods are mostly wrong by chance) and only add to the counts shown.
  const bool boundary_share_off = fit.misfit_area_share > tolerance::kMisfitAreaShare;
  double area = 0.0, misfit_area = 0.0;
  fit.misfit_sensors = 0;
  for (std::size_t i = 0; i < n && i < sensors.size(); ++i) {
    area += std::abs(sensor_area[i]);
    const bool boundaries_off = sensors[i].model_fit_ratio && *sensors[i].model_fit_ratio > options.model_misfit_ratio;
    if (boundaries_off || sensors[i].verdict == SensorVerdict::kModelMisfit)
      ++fit.misfit_sensors, misfit_area += std::abs(sensor_area[i]);
  }
  fit.misfit_area_share = area > 0 ? misfit_area / area : 0.0;
  fit.misfit = fit.known && (boundary_share_off || (fit.reports_median_p && *fit.reports_median_p < tolerance::kMisfitPValue));
  if (!fit.misfit) return;
  // A map the model does not explain as a whole: no verdict of the model stands, in either direction.
  for (SensorAudit& s : sensors) {
    if (s.verdict != SensorVerdict::kConsistent && s.verdict != SensorVerdict::kInconsistent) continue;
    s.reason = "the map as a whole does not follow the path-loss model, so the model's verdict (" + s.reason +
               ") does not stand; not judged";
    s.verdict = SensorVerdict::kModelMisfit;
    s.basis = VerdictBasis::kModelFit;
    s.chi2 = {};
  }
}

}  // namespace covmap::audit::stages
