// covmap::fitting::refine_sites — least-squares refinement of sites and weights from points observed
// on the boundaries of a coverage map (docs/FITTING.md has the model in full).
//
// Contract
//  - Input: initial sites (finite coordinates, finite positive weights); boundary samples, each a
//    finite point p with the indices of the two sites whose cells it separates (in range, a ≠ b,
//    or b = kNone for a point of a's range edge,
//    p not exactly at either initial site, the two not starting at one position) and a finite
//    positive σ; optional priors (site in range, finite values; a σ ≤ 0 switches that part of the
//    prior off, a NaN or infinite σ is an error). Anything else throws std::invalid_argument that
//    lists every problem, each naming the sample/prior/site and what is wrong; invalid
//    RefineOptions throw std::invalid_argument with IsValid's message.
//  - Model: parameters x, y, u = log(weight) per site, and ρ = log R when any sample is a range
//    edge; one residual per sample, its first-order geometric distance from the bisector (or its
//    distance from the range circle) divided by σ (fitting/residuals.h), under a robust loss;
//    priors as independent Gaussian residuals.
//  - Gauge: the boundaries fix positions absolutely but weights only up to one common factor per
//    connected group of sites (sites linked by samples). In a group without weight priors the log
//    weight of its reference site (largest initial weight) is held at its initial value; weight
//    priors, when a group has any, fix the scale instead. Weights are finally divided by the
//    largest, so the largest refined weight is 1. Weights of different groups are comparable only
//    through priors.
//  - Sites without samples are not refined: they take the (precision-weighted) values of their
//    priors where they have any and keep their initial values otherwise (RefineResult::status).
//  - Uncertainty (compute_covariance): ceres::Covariance of each site's block, with the samples'
//    noise level estimated from the residuals when their σ are nominal and the robust loss's
//    efficiency accounted for (fitting/robust_loss.h, fitting/covariance.h).
//  - Guaranteed: a RefineResult for every valid input, whether or not the solver converged
//    (summary.converged, summary.termination; kNoSamples when there is nothing to refine, which
//    counts as converged). Uncertainties the data cannot determine (a site with too few samples, a
//    rank-deficient Jacobian, too few samples to estimate the noise) are marked unavailable, never
//    thrown; summary.message says why.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fitting/tolerances.h"
#include "core/diagram.h"

namespace covmap::fitting {

// A point observed on the boundary between the cells of sites a and b (indices into the sites), or,
// with site_b = kNone, on the range edge of site a: where its coverage ends at the reception limit.
// In the path-loss model a range edge is the circle about the site of radius R·w_a, with one R for
// the whole map (it encodes the receivers' sensitivity); R is estimated with the sites.
struct BoundarySample {
  Point p;
  int site_a = 0;
  int site_b = 0;     // kNone: a range-edge sample of site_a
  double sigma = 1.0;  // 1-σ of p's distance from the boundary, in the units of p
  int chain = 0;       // which boundary chain p came from; carried through for reports only
};

// An optional prior from a reported sensor (its stated precision, taken as calibrated).
struct SitePrior {
  int site = 0;
  Point position;
  double position_sigma = 0.0;  // <= 0: no position prior
  double log_weight = 0.0;      // natural log, in the units of the initial weights
  double log_weight_sigma = 0.0;  // <= 0: no weight prior
};

enum class RobustLoss {
  kNone,    // plain least squares
  kHuber,   // quadratic within loss_scale, linear beyond
  kCauchy,  // log(1 + (r/scale)²): far outliers have almost no influence
};

std::string to_string(RobustLoss loss);  // "none", "huber", "cauchy"
// Parses to_string's names (exactly); false, *loss untouched, for anything else.
bool from_string(std::string_view name, RobustLoss* loss);

// Ends a solve once the sites have settled, before Ceres' own tolerances would: every `window`
// successful iterations (rejected steps move nothing, so they do not count) the sites are compared
// with those of the last comparison, and the solve stops when no more than `moving_share` of the
// sites moved by more than `position_step` (units of the sites' coordinates) or changed their log
// weight by more than `log_weight_step`. On a large map
// the tail of a solve is often a handful of sites creeping along flat valleys (or running off),
// each iteration a full linear solve for all of them; a caller that deals with such sites itself
// (the audit restarts and re-solves them locally) can stop there. Deterministic: it reads only
// the iterates. Not checked at iteration 0; ends with summary.termination kSettled (converged).
struct SettleRule {
  int window = 5;               // successful iterations, >= 1
  double position_step = 0.0;   // > 0
  double log_weight_step = 0.0; // > 0
  double moving_share = 0.0;    // in [0, 1)
};

struct RefineOptions {
  // Robust loss on the sample residuals (priors are never robustified).
  RobustLoss loss = RobustLoss::kCauchy;
  // Where the loss leaves the quadratic regime, in units of the sample σ. Must be > 0.
  double loss_scale = 1.0;
  // Solver iterations (Levenberg–Marquardt steps). Must be >= 1.
  int max_iterations = 200;
  // Stop when an iteration lowers the cost by less than this fraction (Ceres' function tolerance).
  // The default suits exact data; noisy maps (covmap audit) stop far earlier without losing
  // anything their noise would not swamp. Must be > 0.
  double function_tolerance = tolerance::kFunctionTolerance;
  // Ceres' inner iterations: after each step, every site's block is improved with the others held
  // (non-linear block coordinate descent). Far from the optimum on large maps it cuts the number
  // of iterations several-fold. Not with a held reference weight (a site with a partial manifold),
  // so only useful together with weight priors.
  bool inner_iterations = false;
  // Ceres' non-monotonic steps: accept a step that raises the cost a little if the trend is down
  // (helps through the flat, curved valleys of weight ratios).
  bool nonmonotonic_steps = false;
  // Per-site 1-σ uncertainties (ceres::Covariance). Costs about one more solver iteration.
  bool compute_covariance = true;
  // true: sample σ are nominal (relative weights only); the noise level is estimated from the
  // residuals (a robust reduced chi-square) and scales the samples' contribution to the covariance.
  // false: sample σ are calibrated standard deviations and are used as they are.
  bool estimate_noise_scale = true;
  // Threads for the covariance (the solver runs on one: see refine.cpp). Must be >= 1. The
  // result is the same, bit for bit, whatever the count.
  int threads = 1;
  // Print Ceres' per-iteration progress to stdout.
  bool verbose = false;
  // With range-edge samples: hold R at this value (in the units of the initial weights: site i's
  // reach is held_range · initial weight scale) instead of estimating it, e.g. for a local re-solve
  // of part of a map whose R the whole map fixed. Must be finite and > 0 when set.
  std::optional<double> held_range;
  // Stop once the sites have settled (SettleRule); unset: only Ceres' tolerances and max_iterations.
  std::optional<SettleRule> settle;
  // Called after every solver iteration with its number (from 0): a heartbeat for long solves.
  // Empty: not called. Must not throw.
  std::function<void(int iteration)> on_iteration;

  // True when every field is usable; otherwise false with the reason in *error (if not null).
  bool IsValid(std::string* error) const;
};

struct SiteUncertainty {
  // 1-σ of the refined position and the x–y covariance (units of the sites' coordinates).
  double sigma_x = 0.0, sigma_y = 0.0, cov_xy = 0.0;
  // 1-σ of log(weight) relative to log_weight_reference: of log(w_i / w_ref) when the reference is a
  // site (its own sigma is 0: it fixes the scale), of log(w_i) itself (in the priors' units) when
  // the scale is fixed by weight priors (reference kNone). Dividing all weights by the largest
  // shifts every log weight by one number, so this is not changed by the normalisation.
  double sigma_log_weight = 0.0;
  int log_weight_reference = kNone;
  // False when the data (and priors) do not determine the site (its sigmas are then +inf, for a
  // site without samples only the undetermined parts), when the covariance could not be computed
  // or compute_covariance is off (sigmas 0).
  bool available = false;
};

enum class SiteStatus {
  kRefined,     // had samples: refined by least squares
  kFromPrior,   // no samples: position and/or log weight set from its priors, the rest initial
  kUnobserved,  // no samples and no priors: initial values kept
};

std::string to_string(SiteStatus status);  // "refined", "from-prior", "unobserved"

// How a refinement ended: Ceres' termination types, and the two ends of covmap's own.
enum class Termination {
  kNotRun,         // no solve has run (a default summary)
  kConvergence,    // Ceres' CONVERGENCE
  kNoConvergence,  // Ceres' NO_CONVERGENCE: max_iterations reached
  kFailure,        // Ceres' FAILURE
  kUserSuccess,    // Ceres' USER_SUCCESS
  kUserFailure,    // Ceres' USER_FAILURE
  kNoSamples,      // nothing to refine (counts as converged)
  kSettled,        // RefineOptions::settle ended the solve (counts as converged)
};

// Every Termination, in declaration order.
inline constexpr std::array<Termination, 8> kAllTerminations = {
    Termination::kNotRun,      Termination::kConvergence, Termination::kNoConvergence, Termination::kFailure,
    Termination::kUserSuccess, Termination::kUserFailure, Termination::kNoSamples,     Termination::kSettled};

// Ceres' names, "NO_SAMPLES" and "SETTLED"; "" for kNotRun, so that a summary that never ran reads
// as it always has in reports.
std::string to_string(Termination termination);
// Parses to_string's names (exactly); false, *termination untouched, for anything else.
bool from_string(std::string_view name, Termination* termination);

struct RefineSummary {
  bool converged = false;   // Ceres' CONVERGENCE, NO_SAMPLES or SETTLED
  Termination termination = Termination::kNotRun;
  std::string message;      // Ceres' message, then any covariance remark
  int iterations = 0;
  double initial_cost = 0.0, final_cost = 0.0;  // ½ Σ loss(r²), r in σ units, priors included
  double rms_residual = 0.0;   // RMS of sample_residual (units of p)
  std::size_t samples = 0;
  std::size_t sites_without_samples = 0;
  // κ of fitting/robust_loss.h: the covariance treats sample i as having variance κ σ_i² / w_i (w_i
  // its robust weight); the estimated (σ_true/σ)² for plain least squares with nominal σ.
  double noise_variance_factor = 1.0;
  double seconds = 0.0;

  // One line: "CONVERGENCE after 7 iterations, cost 12.3 -> 0.41, rms 0.0011 over 400 samples".
  // Without `seconds`, so that it reads the same on every run of the same input.
  std::string brief() const;
};

struct RefineResult {
  std::vector<Site> sites;             // refined; weights normalized so the largest is 1
  std::vector<SiteUncertainty> uncertainty;     // per site
  std::vector<SiteStatus> status;               // per site
  std::vector<double> sample_residual;          // signed geometric distance per sample, units of p;
                                                // positive on site_b's side of the bisector (for a
                                                // range edge: outside the range circle)
  // The reach R of a site of weight 1 (the largest refined weight), units of p, when any sample
  // is a range edge: site i's coverage ends at R·weight_i. With its 1-σ (0 when not computed).
  std::optional<double> range;
  double range_sigma = 0.0;
  RefineSummary summary;
};

RefineResult refine_sites(std::span<const Site> initial, std::span<const BoundarySample> samples,
                          std::span<const SitePrior> priors = {}, const RefineOptions& options = {});

// RefineResult::sample_residual for other sites (e.g. after a local re-solve): the signed
// geometric distance of each sample from its bisector, or from its range circle of radius
// range·weight (range required when any sample is a range edge; std::invalid_argument otherwise).
std::vector<double> sample_residuals(std::span<const Site> sites, std::span<const BoundarySample> samples,
                                     std::optional<double> range);

}  // namespace covmap::fitting
