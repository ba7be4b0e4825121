// audit::audit — does a coverage map agree with the sensors that drew it?
//
// Pipeline: clean the map into an arc graph (map_cleaning.h); estimate every sensor's
// position and weight from the fitted bisectors with the recognition machinery run with
// tolerances (tolerant_sites.h); refine all of them by robust least squares on points sampled along
// the boundaries (fitting/refine.h); recompute the MWVD of the refined sensors and of the reported
// ones and compare each with the map cell by cell; judge every reported sensor.
//
// Contract: the input is planar (metres; io projects lon/lat first). Sensors reported but absent
// from the map are listed with verdict kNotInMap; cells whose sensor was not reported get no
// verdict. Never throws for a bad fit: a failed stage is reported in the result (stage messages)
// and the later stages work with what they have. Throws std::invalid_argument for an empty map
// and, before any work, MapTooLarge for a map naming more than kMaxSensors; throws
// cleaning::SnapTooSmall when the snap distance is too small for the map. Long solves call
// `progress` at least every tolerance::kHeartbeatSeconds. Deterministic: the same
// input and options give the same result, bit for bit, whatever options.threads, except the
// wall-clock `timings` and `seconds`.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "audit/sensor_verdict.h"
#include "core/coverage_cells.h"
#include "core/reported_sensor.h"
#include "cleaning/map_cleaning.h"
#include "core/diagram.h"

namespace covmap::audit {

// Reported sensors (core/reported_sensor.h) are given in planar map units, with the weight already
// derived from the power when a path-loss exponent was given (io/reported_sensors.h does both).

struct AuditOptions {
  cleaning::CleaningOptions cleaning;
  // Path-loss exponent: weight = 10^(P / (10 alpha)). Needed to turn weights into powers (dB).
  std::optional<double> alpha;
  // Judge a reported sensor inconsistent when its reported values are this unlikely given the map
  // (a chi-square quantile with 3 degrees of freedom: position x, y and log weight). 16.27 is the
  // 99.9 % quantile, so about one consistent sensor in 1000 is flagged by chance.
  double inconsistency_chi2 = 16.27;
  // Model floors added (in quadrature) to the statistical uncertainties before judging. The
  // statistical σ treats the staircase as independent noise; its systematic part (a boundary that
  // is only a few bins from a junction, a cell a few bins wide) is not in it. Measured on generated
  // maps (docs/ACCURACY.md), reconstruction errors stay within about one bin and one dB where the
  // statistical σ alone would flag consistent sensors as bins get coarse; one bin and one dB keep
  // false alarms rare without hiding gross errors (≥ 5 bins, ≥ 6 dB).
  double position_floor_bins = 1.0;
  double power_floor_db = 1.0;
  // A sensor whose boundaries the model fits this many times worse (in mean square) than free
  // curves fitted to each is in a region the model does not explain: it is reported model_misfit,
  // not judged. Under the model the ratio is ~1 (both fits see the same staircase noise): 0.4–1.3
  // on every generated multiplicative map and the bundled ones (docs/ACCURACY.md), while terrain
  // (shadowing) drives it to 10²–10³. (Maps whose boundaries are circles of other sensors, e.g. an
  // exponent per sensor, stay near 1: the reports' statistic of audit/model_fit.h finds those.)
  double model_misfit_ratio = 4.0;
  // Called with (stage name, fraction done in [0, 1]) on long runs; may be empty.
  std::function<void(const std::string&, double)> progress;
  // Worker threads of the cleaning's ring sampling, the refinement's covariance and its
  // independent solves (the starts of the multi-start and the waves of local re-solves), and of
  // the per-sensor verdicts. The result is the same whatever the count (each
  // solve runs on one thread, fitting/refine.cpp says why, and their results are compared in a
  // fixed order).
  int threads = 2;
};

// The most sensors one audit takes. The joint refinement's time grows faster than linearly
// (docs/RELIABILITY.md), so a map of 10⁶ sensors would run for hours; above the limit the audit is
// refused at once with a message that says to split the map into regions.
inline constexpr std::size_t kMaxSensors = 100'000;

// The map names more sensors than kMaxSensors; thrown before any work.
class MapTooLarge : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct SensorAudit {
  std::string id;
  std::string name;                   // the reported name, else the map's (its first cell with one), else empty
  bool in_map = true;                 // false: reported, but no cell of the map names it
  Point position;            // reconstructed (refined), map units
  double weight = 1.0;                // largest = 1
  std::optional<double> tx_power_dbm; // reconstructed, when reported powers (and alpha) fix the scale
  // With alpha: the power relative to the strongest sensor, 10·alpha·log10(weight) (≤ 0 dB); known
  // even when no power was reported, since the map fixes weights up to one common factor.
  std::optional<double> relative_power_db;
  double sigma_x = 0.0, sigma_y = 0.0, cov_xy = 0.0;
  double sigma_position_m = 0.0;      // 1-σ: sqrt of the larger eigenvalue of the 2×2 covariance
  double sigma_log_weight = 0.0;
  bool uncertainty_available = false;
  // Reported values and the comparison, when the sensor was reported.
  std::optional<ReportedSensor> reported;
  double position_error_m = 0.0;      // |reported - reconstructed|
  std::optional<double> power_error_db;  // reported - reconstructed power
  std::optional<double> weight_ratio;    // reported / reconstructed weight, both normalised alike
  // The Mahalanobis distance² behind the verdict; nullopt when the sensor was not judged by it
  // (unreported, undetermined, not in the map), so that reports write null, not a made-up 0.
  std::optional<double> chi2;
  SensorVerdict verdict = SensorVerdict::kUnreported;
  VerdictBasis basis = VerdictBasis::kNone;  // what the verdict rests on; chi2 is set exactly for kBoundaryFit
  std::string reason;                 // one sentence
  // Agreement of this sensor's cell with the map (intersection over union of areas), for the
  // refined and the reported sensors' diagrams (nullopt when not computed).
  std::optional<double> iou_refined;
  std::optional<double> iou_reported;
  // The model-fit ratio of this sensor's boundaries (ModelFit; nullopt without samples).
  std::optional<double> model_fit_ratio;
};

struct DiagramAgreement {
  double mean_iou = 0.0;          // area-weighted over the map's cells
  double hausdorff_m = 0.0;       // between the map's boundaries and the recomputed diagram's
  std::vector<std::string> vanished;  // sensors with a cell in the map but none recomputed
  std::vector<std::string> appeared;  // sensors with a recomputed cell but none in the map
};

// The map's reception limit: where coverage ends against uncovered area that is not the
// map's frame (cleaning's range edges), sensor i's coverage ends at R·w_i with one R for the map.
struct ReceptionLimit {
  double range_m = 0.0;        // R: the reach of a sensor of weight 1 (the strongest), metres
  double range_sigma_m = 0.0;  // its 1-σ (0 when not computed)
  // With reported powers and alpha: the power received at the edge of coverage, p0 − 10·α·log10(R /
  // 1 m) dBm, where p0 is the transmit power of weight 1 — the receivers' sensitivity up to the
  // model's constant loss at 1 m (the same for every sensor, so differences between maps are exact).
  std::optional<double> sensitivity_dbm;
  std::size_t sensors = 0;     // sensors whose coverage ends at a range edge somewhere
};

// How well the multiplicative model explains the map (audit/model_fit.h has both statistics):
// (1) the mean square of the model's boundary residuals over that of free curves fitted to each
// boundary on its own, ~1 where the map follows the model; (2) the reported sensors
// against the map: where the model holds and the reports are right but for a few gross errors, most
// sensors' χ² tail probabilities are large; a region (or map) where most are small is not drawn by
// the model the reports describe (e.g. every sensor its own path-loss exponent: the boundaries are
// still circles, of other sensors).
struct ModelFit {
  bool known = false;             // false: the refinement did not run, nothing was measured
  double ratio = 0.0;             // (1) over the whole map
  // (2) the median χ² tail probability over the sensors the boundary fit judged (nullopt with
  // fewer than tolerance::kMisfitMinJudged of them).
  std::optional<double> reports_median_p;
  std::size_t misfit_sensors = 0; // sensors marked model_misfit (either statistic)
  double misfit_area_share = 0.0; // their share of the map's covered area
  // The map as a whole does not follow the model: more than tolerance::kMisfitAreaShare of its area
  // in sensors whose boundaries the model does not draw (statistic 1; the pooled ratio is shown, not
  // decided on: a few sensors can dominate a mean square), or the reports' median p below
  // tolerance::kMisfitPValue (statistic 2).
  bool misfit = false;
};

// The path-loss exponent the map and the reported powers imply (audit/alpha_estimate.h): an
// interval, since both the refined weights and the reported powers carry errors. The regression
// of power on log weight gives its low end, the one of log weight on power its high end; the true
// exponent lies between them, each end known to its own σ.
struct AlphaEstimate {
  double low = 0.0, high = 0.0;              // high is +infinity when the powers do not vary with the weights
  double sigma_low = 0.0, sigma_high = 0.0;  // 1-σ of each end (infinity with high)
  std::size_t sensors = 0;      // sensors in the final fit
  std::size_t outliers = 0;     // sensors left out as gross errors
  // The given --alpha lies more than tolerance::kAlphaDisagreementSigmas σ outside [low, high]
  // (false without a given alpha).
  bool disagrees = false;
};

// Wall-clock time of one stage of the audit.
struct StageTiming {
  std::string stage;
  double seconds = 0.0;
};

// Every member but `timings` and `seconds` is the same, bit for bit, on every run of the same input
// and options, whatever options.threads; those two are wall-clock times, kept apart.
struct AuditResult {
  std::vector<SensorAudit> sensors;   // map sensors first (map order), then reported-only ones
  cleaning::CleanedMap cleaned;
  Diagram refined_diagram;   // MWVD of the refined sensors, clipped to the map's frame
  std::optional<Diagram> reported_diagram;  // same for the reported sensors
  std::optional<ReceptionLimit> reception;  // when the map has range edges
  ModelFit model_fit;
  std::optional<AlphaEstimate> alpha_estimate;  // when reported powers and the map determine it
  DiagramAgreement refined_agreement;
  std::optional<DiagramAgreement> reported_agreement;
  double bin_size_m = 0.0;
  std::size_t boundary_samples = 0;
  std::string refinement_summary;     // fitting's brief report (solver words, for analysts)
  bool refinement_converged = false;  // the solver reached its tolerance (reports say so in plain words)
  std::vector<std::string> messages;  // notable events of each stage, for the report (no times)
  std::vector<StageTiming> timings;   // per stage, in order
  double seconds = 0.0;               // the whole audit (the CLI adds its reading of the inputs)
};

AuditResult audit(std::span<const CoverageCell> map, std::span<const ReportedSensor> reported,
                  const AuditOptions& options = {});

}  // namespace covmap::audit
