// refine_sites: validate, lay out the problem, solve, then uncertainty, unobserved sites, and the
// normalisation of the weights. The pieces live in problem_setup, robust_loss and covariance.
#include "fitting/refine.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include <ceres/solver.h>

#include "fitting/covariance.h"
#include "fitting/inner_ordering.h"
#include "fitting/problem_setup.h"
#include "fitting/robust_loss.h"
#include "fitting/serial_factorization.h"
#include "fitting/settled_sites.h"
#include "fitting/solver_logging.h"
#include "fitting/tolerances.h"
#include "fitting/validate.h"

namespace covmap::fitting {
namespace {

using detail::SiteBlock;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Forwards Ceres' iterations to RefineOptions::on_iteration.
class Heartbeat : public ceres::IterationCallback {
 public:
  explicit Heartbeat(const std::function<void(int)>& beat) : beat_(beat) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    beat_(summary.iteration);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const std::function<void(int)>& beat_;
};

Termination termination_of(ceres::TerminationType type) {
  switch (type) {
    case ceres::CONVERGENCE: return Termination::kConvergence;
    case ceres::NO_CONVERGENCE: return Termination::kNoConvergence;
    case ceres::FAILURE: return Termination::kFailure;
    case ceres::USER_SUCCESS: return Termination::kUserSuccess;
    case ceres::USER_FAILURE: return Termination::kUserFailure;
  }
  return Termination::kFailure;
}

ceres::Solver::Options solver_options(const RefineOptions& options) {
  ceres::Solver::Options solver;
  solver.max_num_iterations = options.max_iterations;
  // One thread, whatever options.threads: Ceres' evaluator hands residual blocks to its threads
  // dynamically and adds each thread's partial cost and gradient in turn, so with more threads the
  // sums, hence the accepted steps and the result, would depend on scheduling. The covariance
  // (covariance.cpp) keeps the threads: it computes each block independently.
  solver.num_threads = 1;
  solver.function_tolerance = options.function_tolerance;
  solver.use_inner_iterations = options.inner_iterations;
  solver.use_nonmonotonic_steps = options.nonmonotonic_steps;
  solver.parameter_tolerance = tolerance::kParameterTolerance;
  solver.gradient_tolerance = tolerance::kGradientTolerance;
  // Each sample couples two sites: the normal equations are as sparse as the map's adjacency.
  if (ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::SUITE_SPARSE)) {
    solver.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    solver.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
  } else if (ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::EIGEN_SPARSE)) {
    solver.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    solver.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
  } else {
    solver.linear_solver_type = ceres::DENSE_QR;
  }
  solver.minimizer_progress_to_stdout = options.verbose;
  solver.logging_type = options.verbose ? ceres::PER_MINIMIZER_ITERATION : ceres::SILENT;
  return solver;
}

// Ceres's inner-iteration groups from independent_rounds (inner_ordering.h). Ceres runs groups in
// increasing order; the last (smallest) round found goes first, as in its own ordering.
std::shared_ptr<ceres::ParameterBlockOrdering> inner_ordering(std::vector<SiteBlock>& blocks, const detail::Layout& layout,
                                                               std::span<const BoundarySample> samples) {
  const auto rounds = detail::independent_rounds(blocks.size(), samples, layout.sample_count);
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  for (std::size_t r = 0; r < rounds.size(); ++r)
    for (int v : rounds[r]) ordering->AddElementToGroup(blocks[v].data(), static_cast<int>(rounds.size() - 1 - r));
  return ordering;
}

// Precision-weighted combination of several independent Gaussian estimates of one quantity.
struct Combined {
  double precision = 0.0;  // Σ 1/σ²
  double weighted = 0.0;   // Σ value/σ²
  void add(double value, double sigma) {
    precision += 1.0 / (sigma * sigma);
    weighted += value / (sigma * sigma);
  }
  bool any() const { return precision > 0; }
  double mean() const { return weighted / precision; }
  double sigma() const { return any() ? 1.0 / std::sqrt(precision) : kInfinity; }
};

// Sites without samples: set from their priors (SiteStatus::kFromPrior) or left as they were.
void settle_unobserved(std::vector<SiteBlock>& blocks, const detail::Layout& layout, std::span<const SitePrior> priors,
                       const RefineOptions& options, RefineResult& result) {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (layout.sample_count[i] > 0) continue;
    ++result.summary.sites_without_samples;
    Combined x, y, u;
    for (const SitePrior& p : priors) {
      if (static_cast<std::size_t>(p.site) != i) continue;
      if (p.position_sigma > 0) {
        x.add(p.position.x, p.position_sigma);
        y.add(p.position.y, p.position_sigma);
      }
      if (p.log_weight_sigma > 0) u.add(p.log_weight, p.log_weight_sigma);
    }
    if (x.any()) {
      blocks[i][0] = x.mean();
      blocks[i][1] = y.mean();
    }
    if (u.any()) blocks[i][kLogWeightIndex] = u.mean();
    result.status[i] = (x.any() || u.any()) ? SiteStatus::kFromPrior : SiteStatus::kUnobserved;
    if (options.compute_covariance) {
      SiteUncertainty& s = result.uncertainty[i];
      s.sigma_x = x.sigma();
      s.sigma_y = y.sigma();
      s.sigma_log_weight = u.sigma();
      s.log_weight_reference = kNone;
      s.available = x.any() && u.any();
    }
  }
}

}  // namespace

RefineResult refine_sites(std::span<const Site> initial, std::span<const BoundarySample> samples,
                          std::span<const SitePrior> priors, const RefineOptions& options) {
  detail::quiet_solver_logging();
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument("refine_sites: invalid options: " + error);
  detail::validate_inputs(initial, samples, priors);

  detail::Layout layout = detail::make_layout(initial, samples, priors);
  if (layout.range && options.held_range) {
    layout.hold_range = true;
    --layout.free_parameters;
  }
  std::vector<SiteBlock> blocks = detail::initial_blocks(initial);
  double log_range = options.held_range ? std::log(*options.held_range) : detail::initial_log_range(blocks, samples);
  const std::unique_ptr<ceres::LossFunction> loss = detail::make_loss(options.loss, options.loss_scale);

  RefineResult result;
  result.uncertainty.resize(initial.size());
  result.status.assign(initial.size(), SiteStatus::kRefined);
  RefineSummary& summary = result.summary;
  summary.samples = samples.size();

  if (samples.empty()) {
    summary.converged = true;
    summary.termination = Termination::kNoSamples;
    summary.message = "no boundary samples: nothing to refine";
  } else {
    detail::BuiltProblem built = detail::build_problem(blocks, &log_range, layout, samples, priors, loss.get());
    ceres::Solver::Summary solved;
    ceres::Solver::Options solver = solver_options(options);
    if (solver.use_inner_iterations) solver.inner_iteration_ordering = inner_ordering(blocks, layout, samples);
    Heartbeat heartbeat(options.on_iteration);
    (void)detail::keep_sparse_factorization_serial();
    if (options.on_iteration) solver.callbacks.push_back(&heartbeat);
    std::optional<detail::SettledSites> settle;
    if (options.settle) {
      settle.emplace(blocks, *options.settle);
      solver.update_state_every_iteration = true;
      solver.callbacks.push_back(&*settle);
    }
    ceres::Solve(solver, built.problem.get(), &solved);
    summary.converged = solved.termination_type == ceres::CONVERGENCE;
    summary.termination = termination_of(solved.termination_type);
    summary.message = solved.message;
    if (settle && settle->settled()) {
      summary.converged = true;
      summary.termination = Termination::kSettled;
      summary.message = std::to_string(settle->still_moving()) + " of " + std::to_string(blocks.size()) +
                        " sites still moving (RefineOptions::settle)";
    }
    summary.iterations = solved.num_successful_steps + solved.num_unsuccessful_steps;
    summary.initial_cost = solved.initial_cost;
    summary.final_cost = solved.final_cost;
  }

  result.sample_residual.reserve(samples.size());
  std::vector<double> r_sigma;  // σ units, for the noise estimate
  r_sigma.reserve(samples.size());
  double sum_squares = 0.0;
  for (const BoundarySample& s : samples) {
    const double r = detail::geometric_residual(blocks, log_range, s);
    result.sample_residual.push_back(r);
    r_sigma.push_back(r / s.sigma);
    sum_squares += r * r;
  }
  if (!samples.empty()) summary.rms_residual = std::sqrt(sum_squares / samples.size());

  if (options.compute_covariance && !samples.empty()) {
    const detail::SolvedProblem solution{
        .layout = layout, .samples = samples, .priors = priors, .loss = loss.get(), .residuals = r_sigma};
    detail::CovarianceOutcome covariance = detail::site_covariance(blocks, &log_range, solution, options);
    result.range_sigma = covariance.log_range_sigma;  // of log R: relative, scaled below
    result.uncertainty = std::move(covariance.uncertainty);
    summary.noise_variance_factor = covariance.variance_factor;
    if (!covariance.remark.empty()) summary.message += (summary.message.empty() ? "" : "; ") + covariance.remark;
  }
  settle_unobserved(blocks, layout, priors, options, result);

  // Largest weight 1: subtract the largest log weight (no overflow for any weight ratio).
  double largest = -kInfinity;
  for (const SiteBlock& b : blocks) largest = std::max(largest, b[kLogWeightIndex]);
  result.sites.reserve(initial.size());
  for (std::size_t i = 0; i < initial.size(); ++i) {
    result.sites.push_back({initial[i].id, blocks[i][0], blocks[i][1], std::exp(blocks[i][kLogWeightIndex] - largest)});
  }
  // R·w is invariant: dividing the weights by the largest multiplies R by it.
  if (layout.range) {
    result.range = std::exp(log_range + largest);
    result.range_sigma *= *result.range;
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<double> sample_residuals(std::span<const Site> sites, std::span<const BoundarySample> samples,
                                     std::optional<double> range) {
  const std::vector<SiteBlock> blocks = detail::initial_blocks(sites);
  const bool any_range = std::any_of(samples.begin(), samples.end(), [](const BoundarySample& s) { return s.site_b == kNone; });
  if (any_range && !range) throw std::invalid_argument("sample_residuals: range-edge samples need the range R");
  const double log_range = range ? std::log(*range) : 0.0;
  std::vector<double> out;
  out.reserve(samples.size());
  for (const BoundarySample& s : samples) out.push_back(detail::geometric_residual(blocks, log_range, s));
  return out;
}

}  // namespace covmap::fitting
