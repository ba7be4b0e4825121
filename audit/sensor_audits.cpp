// Verdicts per sensor for audit(): the common factor of reported and reconstructed weights, and per
// sensor its reconstruction, uncertainty (local_uncertainty.h says why conditional) and verdict.
#include <cmath>

#include "audit/audit_stages.h"
#include "audit/verdict.h"
#include "fitting/local_uncertainty.h"

namespace covmap::audit::stages {
namespace {

// The reported weight, or the weight of the reported power (with alpha).
std::optional<double> reported_weight(const ReportedSensor& r, const AuditOptions& options) {
  std::optional<double> w = r.weight;
  if (!w && r.tx_power_dbm && options.alpha) w = std::pow(10.0, *r.tx_power_dbm / (10.0 * *options.alpha));
  return w;
}

// The verdict on a reported map sensor: its difference from the reconstruction s against the
// uncertainty u.
void judge_reported(const ReportedSensor& r, const fitting::LocalUncertainty& u, const WeightScale& scale,
                    const RefinementSetup& setup, const AuditOptions& options, SensorAudit& s) {
  s.reported = r;
  const double dx = r.position.x - s.position.x, dy = r.position.y - s.position.y;
  s.position_error_m = std::hypot(dx, dy);
  VerdictInput vi;
  vi.dx = dx, vi.dy = dy;
  const std::optional<double> w = reported_weight(r, options);
  if (w && *w > 0) {
    vi.dlogw = std::log(*w) - std::log(s.weight) - scale.log_factor;
    s.weight_ratio = std::exp(*vi.dlogw);
    if (options.alpha) s.power_error_db = *vi.dlogw / scale.logw_per_db;
  }
  vi.var_x = u.sigma_x * u.sigma_x, vi.var_y = u.sigma_y * u.sigma_y, vi.cov_xy = u.cov_xy;
  vi.var_logw = u.sigma_log_weight * u.sigma_log_weight;
  vi.reported_position_sigma = r.position_sigma_m.value_or(0.0);
  if (r.power_sigma_db) vi.reported_logw_sigma = *r.power_sigma_db * scale.logw_per_db;
  vi.position_floor = options.position_floor_bins * setup.bin_size_m;
  vi.logw_floor = options.power_floor_db * scale.logw_per_db;
  vi.alpha = options.alpha;
  if (!u.available || s.sigma_position_m > 0.5 * setup.prior_position_sigma) {
    s.verdict = SensorVerdict::kUndetermined;
    s.reason = "the map does not determine this sensor (too few boundary points); not judged";
  } else {
    const Judgement v = judge(vi, options.inconsistency_chi2);
    s.chi2 = v.chi2;
    s.verdict = v.inconsistent ? SensorVerdict::kInconsistent : SensorVerdict::kConsistent;
    s.reason = v.reason;
  }
}

}  // namespace

// Powers and the common factor of weights: reported and reconstructed weights are each known
// only up to a factor; the factor between them is the median of their log ratios.
WeightScale weight_scale(const fitting::RefineResult& refined, const ReportedOf& reported_of,
                         const AuditOptions& options) {
  const double ln10 = std::log(10.0);
  std::vector<double> log_ratios, power_offsets;
  for (auto [i, r] : reported_of) {
    const std::optional<double> w = reported_weight(*r, options);
    if (w && *w > 0) log_ratios.push_back(std::log(*w) - std::log(refined.sites[i].weight));
    if (r->tx_power_dbm && options.alpha)
      power_offsets.push_back(*r->tx_power_dbm - 10.0 * *options.alpha * std::log10(refined.sites[i].weight));
  }
  WeightScale scale;
  scale.log_factor = median(log_ratios);
  scale.p0 = power_offsets.empty() ? std::nullopt : std::optional<double>(median(power_offsets));
  scale.logw_per_db = options.alpha ? ln10 / (10.0 * *options.alpha) : ln10 / (10.0 * 3.5);
  return scale;
}

std::vector<SensorAudit> sensor_audits(const cleaning::CleanedMap& cleaned, const MapCells& cells,
                                       const fitting::RefineResult& refined, const RefinementSetup& setup,
                                       const ReportedOf& reported_of, std::span<const ReportedSensor> reported,
                                       const WeightScale& scale, const AuditOptions& options) {
  std::vector<SensorAudit> sensors;
  const std::size_t n = setup.n;
  const std::vector<fitting::LocalUncertainty> local =
      fitting::local_uncertainty(refined.sites, setup.samples, setup.options.loss_scale, refined.range);
  for (std::size_t i = 0; i < n; ++i) {
    SensorAudit s;
    s.id = cleaned.sensors[i];
    s.position = {refined.sites[i].x, refined.sites[i].y};
    s.weight = refined.sites[i].weight;
    if (scale.p0 && options.alpha) s.tx_power_dbm = *scale.p0 + 10.0 * *options.alpha * std::log10(s.weight);
    if (options.alpha) s.relative_power_db = 10.0 * *options.alpha * std::log10(s.weight);
    const fitting::LocalUncertainty& u = local[i];
    s.uncertainty_available = u.available;
    s.sigma_x = u.sigma_x, s.sigma_y = u.sigma_y, s.cov_xy = u.cov_xy, s.sigma_log_weight = u.sigma_log_weight;
    {
      const double a = u.sigma_x * u.sigma_x, b = u.sigma_y * u.sigma_y, c = u.cov_xy;
      s.sigma_position_m = std::sqrt(0.5 * (a + b) + std::sqrt(0.25 * (a - b) * (a - b) + c * c));
    }
    if (auto it = reported_of.find(static_cast<int>(i)); it != reported_of.end())
      judge_reported(*it->second, u, scale, setup, options, s);
    sensors.push_back(std::move(s));
  }
  for (const ReportedSensor& r : reported) {
    if (cells.index.count(r.id)) continue;
    SensorAudit s;
    s.id = r.id;
    s.in_map = false;
    s.position = r.position;
    s.reported = r;
    s.verdict = SensorVerdict::kNotInMap;
    s.reason = "reported, but no cell of the map names it";
    sensors.push_back(std::move(s));
  }
  return sensors;
}

}  // namespace covmap::audit::stages
