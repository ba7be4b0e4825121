// Verdicts per sensor for audit(): the common factor of reported and reconstructed weights, and per
// sensor its reconstruction, uncertainty (local_uncertainty.h says why conditional) and verdict.
#include <cmath>
#include <exception>

#include "audit/audit_stages.h"
#include "audit/cell_evidence.h"
#include "audit/tolerances.h"
#include "core/readable_numbers.h"
#include "audit/verdict.h"
#include "core/parallel.h"
#include "fitting/local_uncertainty.h"

namespace covmap::audit::stages {
namespace {

// What judging one sensor needs of the audit.
struct AuditContext {
  const cleaning::CleanedMap& cleaned;
  const fitting::RefineResult& refined;
  const RefinementSetup& setup;
  const WeightScale& scale;
  const AuditOptions& options;
  const MapRaster& raster;
  const MapCells& cells;
  std::vector<BinWindow> windows;  // per map sensor: its cell's bins (cell_evidence.h)
  double chi2_two_dof;  // the 2-dof threshold of the same tail probability as options.inconsistency_chi2
};

// The reported weight, or the weight of the reported power (with alpha).
std::optional<double> reported_weight(const ReportedSensor& r, const AuditOptions& options) {
  std::optional<double> w = r.weight;
  if (!w && r.tx_power_dbm && options.alpha) w = std::pow(10.0, *r.tx_power_dbm / (10.0 * *options.alpha));
  return w;
}

// The reported sensor's sites: the refined ones with sensor i at its reported position and (in the
// refined weights' scale) weight; a sensor without a reported strength keeps its refined weight.
std::vector<Site> with_reported(const std::vector<Site>& refined, std::size_t i, const ReportedSensor& r,
                                const WeightScale& scale, const AuditOptions& options) {
  std::vector<Site> sites = refined;
  if (i == sites.size()) sites.push_back({r.id, r.position.x, r.position.y, 1.0});
  sites[i].x = r.position.x, sites[i].y = r.position.y;
  if (const std::optional<double> w = reported_weight(r, options); w && *w > 0) sites[i].weight = *w / std::exp(scale.log_factor);
  return sites;
}

std::string percent(double f) { return fixed(100.0 * f, 0) + " %"; }

// The reported values moved toward the reconstruction by `t` of the way (t = 0: as reported).
std::vector<Site> toward_refined(std::vector<Site> sites, std::size_t i, const Site& refined, double t) {
  Site& s = sites[i];
  s.x += t * (refined.x - s.x), s.y += t * (refined.y - s.y);
  s.weight = std::exp(std::log(s.weight) + t * (std::log(refined.weight) - std::log(s.weight)));
  return sites;
}

// The verdict on a sensor whose boundaries do not pin it down, from its cell (cell_evidence.h):
// is its reported position outside its own cell, and can any values within the report's own
// uncertainty (its stated σ and the floors, to the χ² threshold) draw the mapped cell? The values
// tried are those nearest the reconstruction, which draws it (overlap ≥ kCellModelOverlap).
void judge_by_cell(const ReportedSensor& r, std::size_t i, const VerdictInput& vi, const AuditContext& c, SensorAudit& s) {
  s.basis = VerdictBasis::kCell;
  const double sigma_p = std::hypot(vi.reported_position_sigma, vi.position_floor);
  const double allowed_distance = std::sqrt(c.chi2_two_dof) * sigma_p;
  const CellDistance where = distance_to_cell(c.raster, c.windows[i], static_cast<int>(i), r.position);
  if (where.host != kNone && where.host != static_cast<int>(i) && where.metres > allowed_distance) {
    s.verdict = SensorVerdict::kInconsistent;
    s.reason = "its reported position lies in the cell of " + c.cleaned.sensors[where.host] + ", " + metres(where.metres) +
               " from its own cell (a sensor always lies in its own cell; allowed " + metres(allowed_distance) + ")";
    return;
  }
  const PredictedCell refined = predicted_cell(c.raster, c.windows[i], c.refined.sites, static_cast<int>(i), c.refined.range);
  if (refined.iou < tolerance::kCellModelOverlap) {
    s.basis = VerdictBasis::kNone;
    s.verdict = SensorVerdict::kUndetermined;
    s.reason = refined.mapped_bins < tolerance::kResolvedCellBins
                   ? "its cell is only " + plural(refined.mapped_bins, "bin") +
                         " of the map: too small for the map to tell where it is or how strong; not judged"
                   : "the map does not pin this sensor down and the model explains its cell poorly (overlap " +
                         percent(refined.iou) + "): not judged";
    return;
  }
  // How far the report lies from the reconstruction in its own uncertainty (Mahalanobis).
  double m2 = (vi.dx * vi.dx + vi.dy * vi.dy) / (sigma_p * sigma_p);
  double limit2 = c.chi2_two_dof;
  if (vi.dlogw) {
    const double sigma_w = std::hypot(vi.reported_logw_sigma.value_or(0.0), vi.logw_floor);
    m2 += *vi.dlogw * *vi.dlogw / (sigma_w * sigma_w);
    limit2 = c.options.inconsistency_chi2;
  }
  const std::vector<Site> as_reported = with_reported(c.refined.sites, i, r, c.scale, c.options);
  const PredictedCell reported = predicted_cell(c.raster, c.windows[i], as_reported, static_cast<int>(i), c.refined.range);
  const double t = m2 > limit2 ? 1.0 - std::sqrt(limit2 / m2) : 1.0;
  const PredictedCell nearest =
      t >= 1.0 ? refined
               : predicted_cell(c.raster, c.windows[i], toward_refined(as_reported, i, c.refined.sites[i], t), static_cast<int>(i),
                                c.refined.range);
  const std::string overlaps = "overlaps the mapped cell by " + percent(reported.iou) + " as reported, by " +
                               percent(nearest.iou) + " at the nearest values its stated uncertainty allows (the reconstruction's by " +
                               percent(refined.iou) + ")";
  // The overlap a right report can lose against the reconstruction's: its whole boundary moved by
  // one bin (the map's own resolution), about 4·√A bins of a cell of A bins.
  const double a = static_cast<double>(refined.mapped_bins);
  const double allowed_loss = a > 0 ? 1.0 - a / (a + 4.0 * std::sqrt(a)) : 1.0;
  if (nearest.iou < std::max(tolerance::kPredictedOverlap, refined.iou - allowed_loss)) {
    s.verdict = SensorVerdict::kInconsistent;
    s.reason = "its boundaries do not pin it down, but its predicted cell " + overlaps;
  } else {
    s.verdict = SensorVerdict::kConsistent;
    s.reason = "its boundaries do not pin it down; its reported position fits its own cell and its predicted cell " + overlaps;
  }
}

// The verdict on a reported map sensor: its difference from the reconstruction s against the
// uncertainty u; by its cell where u does not pin it down.
void judge_reported(const ReportedSensor& r, std::size_t i, const fitting::LocalUncertainty& u, const AuditContext& c,
                    SensorAudit& s) {
  s.reported = r;
  const WeightScale& scale = c.scale;
  const AuditOptions& options = c.options;
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
  vi.position_floor = options.position_floor_bins * c.setup.bin_size_m;
  vi.logw_floor = options.power_floor_db * scale.logw_per_db;
  vi.alpha = options.alpha;
  // The χ² test takes the boundary samples' errors as independent; along the few staircase steps
  // of a cell below the map's resolution they are not, and the local σ is too small.
  const double cell_bins = std::abs(c.cells.area[i]) / (c.setup.bin_size_m * c.setup.bin_size_m);
  if (!u.available || s.sigma_position_m > 0.5 * c.setup.prior_position_sigma || cell_bins < tolerance::kResolvedCellBins) {
    judge_by_cell(r, i, vi, c, s);
    return;
  }
  const Judgement v = judge(vi, options.inconsistency_chi2);
  s.basis = VerdictBasis::kBoundaryFit;
  s.chi2 = v.chi2;
  s.verdict = v.inconsistent ? SensorVerdict::kInconsistent : SensorVerdict::kConsistent;
  s.reason = v.reason;
}

// A sensor reported but absent from the map: would its reported position and power give it a cell?
void judge_absent(const ReportedSensor& r, const AuditContext& c, SensorAudit& s) {
  if (!reported_weight(r, c.options)) {
    s.verdict = SensorVerdict::kNotInMap;
    s.reason = "reported, but no cell of the map names it; without a reported power its cell cannot be predicted";
    return;
  }
  s.basis = VerdictBasis::kPrediction;
  const std::size_t k = c.refined.sites.size();
  std::vector<Site> sites = with_reported(c.refined.sites, k, r, c.scale, c.options);
  const auto bins_at = [&](const std::vector<Site>& at) {
    return predicted_cell(c.raster, BinWindow{}, at, static_cast<int>(k), c.refined.range,
                          tolerance::kPredictionSearchSpacings * c.setup.spacing)
        .predicted_bins;
  };
  const std::size_t as_reported = bins_at(sites);
  // The weakest power its stated uncertainty (and the floor) allows, to the χ² threshold: a right
  // report whose sensor the map's bins just missed must not be blamed for a power 1 dB high.
  const double sigma_logw =
      std::hypot(r.power_sigma_db.value_or(0.0), c.options.power_floor_db) * c.scale.logw_per_db;
  sites[k].weight *= std::exp(-std::sqrt(c.chi2_two_dof) * sigma_logw);
  const std::size_t weakest = bins_at(sites);
  const double bin = c.raster.grid.bin;
  const auto area = [&](std::size_t bins) { return fixed(static_cast<double>(bins) * bin * bin / 1e6, 2) + " km²"; };
  if (weakest >= tolerance::kMinPredictedBins) {
    s.verdict = SensorVerdict::kInconsistent;
    s.reason = "no cell of the map names it, but with its reported position and power it would serve " +
               std::to_string(as_reported) + " bins (" + area(as_reported) + ") of the map, and " +
               std::to_string(weakest) + " even at the weakest power its stated uncertainty allows";
  } else {
    s.verdict = SensorVerdict::kConsistent;
    s.reason = "no cell of the map names it, and within its stated uncertainty its reported position and power give it " +
               std::to_string(weakest) + " bins of the map (" + std::to_string(as_reported) + " as reported), as the map shows";
  }
}

// Map sensor i: its reconstruction, uncertainty and, when reported, verdict.
void judge_map_sensor(std::size_t i, const AuditContext& c, const ReportedOf& reported_of, const MapCells& cells,
                      const fitting::LocalUncertainty& u, SensorAudit& s) {
  const Site& site = c.refined.sites[i];
  s.id = c.cleaned.sensors[i];
  s.position = {site.x, site.y};
  s.weight = site.weight;
  if (c.scale.p0 && c.options.alpha) s.tx_power_dbm = *c.scale.p0 + 10.0 * *c.options.alpha * std::log10(s.weight);
  if (c.options.alpha) s.relative_power_db = 10.0 * *c.options.alpha * std::log10(s.weight);
  s.uncertainty_available = u.available;
  s.sigma_x = u.sigma_x, s.sigma_y = u.sigma_y, s.cov_xy = u.cov_xy, s.sigma_log_weight = u.sigma_log_weight;
  {
    const double a = u.sigma_x * u.sigma_x, b = u.sigma_y * u.sigma_y, xy = u.cov_xy;
    s.sigma_position_m = std::sqrt(0.5 * (a + b) + std::sqrt(0.25 * (a - b) * (a - b) + xy * xy));
  }
  const auto it = reported_of.find(static_cast<int>(i));
  // The operator's name for the sensor first: the map's is often an export's label.
  s.name = it != reported_of.end() && !it->second->name.empty() ? it->second->name : cells.names[i];
  if (it != reported_of.end()) judge_reported(*it->second, i, u, c, s);
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

std::vector<SensorAudit> sensor_audits(const VerificationInputs& in) {
  const RefinementSetup& setup = in.setup;
  const fitting::RefineResult& refined = in.refined;
  const MapCells& cells = in.cells;
  const AuditOptions& options = in.options;
  std::vector<SensorAudit> sensors;
  const AuditContext context{.cleaned = in.cleaned,
                             .refined = refined,
                             .setup = setup,
                             .scale = in.scale,
                             .options = options,
                             .raster = in.raster,
                             .cells = cells,
                             .windows = cell_windows(in.raster, setup.n),
                             .chi2_two_dof = chi2_quantile_two_dof(options.inconsistency_chi2)};
  const std::size_t n = setup.n;
  const std::vector<fitting::LocalUncertainty> local =
      fitting::local_uncertainty(refined.sites, setup.samples, setup.options.loss_scale, refined.range);
  // Each map sensor is judged on its own (its predicted cells are small rasters of their own), into
  // its own slot: on the audit's threads, the same whatever their count.
  // An exception is kept per sensor and the first sensor's thrown after, as the plain loop would.
  sensors.resize(n);
  std::vector<std::exception_ptr> failed(n);
  parallel_items(n, options.threads, [&](std::size_t i) {
    try {
      judge_map_sensor(i, context, in.reported_of, cells, local[i], sensors[i]);
    } catch (...) {
      failed[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  for (const ReportedSensor& r : in.reported) {
    if (cells.index.count(r.id)) continue;
    SensorAudit s;
    s.id = r.id;
    s.name = r.name;
    s.in_map = false;
    s.position = r.position;
    s.reported = r;
    judge_absent(r, context, s);
    sensors.push_back(std::move(s));
  }
  return sensors;
}

}  // namespace covmap::audit::stages
