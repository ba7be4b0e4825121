#include "fitting/covariance.h"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <ceres/covariance.h>
#include <ceres/crs_matrix.h>

#include "fitting/robust_loss.h"
#include "fitting/tolerances.h"

namespace covmap::fitting::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::vector<int> observed_sites(const Layout& layout) {
  std::vector<int> sites;
  for (std::size_t i = 0; i < layout.sample_count.size(); ++i) {
    if (layout.sample_count[i] > 0) sites.push_back(static_cast<int>(i));
  }
  return sites;
}

// Computes the diagonal blocks of `sites`; false when Ceres reports a rank-deficient Jacobian.
// With log_range (not null): its variance too, into *log_range_sigma.
bool compute_blocks(ceres::Problem& problem, std::vector<SiteBlock>& blocks, const std::vector<int>& sites,
                    int threads, std::vector<SiteUncertainty>& out, double* log_range = nullptr,
                    double* log_range_sigma = nullptr) {
  ceres::Covariance::Options covariance_options;
  covariance_options.num_threads = threads;
  ceres::Covariance covariance(covariance_options);
  std::vector<std::pair<const double*, const double*>> wanted;
  for (int i : sites) wanted.emplace_back(blocks[i].data(), blocks[i].data());
  if (log_range) wanted.emplace_back(log_range, log_range);
  if (!covariance.Compute(wanted, &problem)) return false;
  if (log_range) {
    double v = 0.0;
    if (covariance.GetCovarianceBlock(log_range, log_range, &v)) *log_range_sigma = std::sqrt(v);
  }
  for (int i : sites) {
    double c[kSiteBlockSize * kSiteBlockSize];
    if (!covariance.GetCovarianceBlock(blocks[i].data(), blocks[i].data(), c)) return false;
    SiteUncertainty& u = out[i];
    u.sigma_x = std::sqrt(c[0]);
    u.sigma_y = std::sqrt(c[4]);
    u.cov_xy = c[1];
    u.sigma_log_weight = std::sqrt(c[8]);
    u.available = std::isfinite(u.sigma_x) && std::isfinite(u.sigma_y) && std::isfinite(u.sigma_log_weight);
  }
  return true;
}

// Shares of the (near) null space of a symmetric positive semi-definite matrix, per column, after
// scaling it to a unit diagonal (so lengths and log weights compare). A zero column has share 1.
std::vector<double> null_space_shares(const Eigen::MatrixXd& normal) {
  const Eigen::Index n = normal.rows();
  Eigen::VectorXd scale(n);
  std::vector<double> share(n, 0.0);
  for (Eigen::Index j = 0; j < n; ++j) {
    scale(j) = normal(j, j) > 0 ? 1.0 / std::sqrt(normal(j, j)) : 0.0;
    if (!(normal(j, j) > 0)) share[j] = 1.0;
  }
  const Eigen::MatrixXd scaled = scale.asDiagonal() * normal * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(scaled);
  if (eigen.info() != Eigen::Success) return std::vector<double>(n, 1.0);
  const double largest = eigen.eigenvalues().maxCoeff();
  for (Eigen::Index k = 0; k < n; ++k) {
    if (eigen.eigenvalues()(k) > tolerance::kNullEigenvalue * largest) continue;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (scale(j) > 0) share[j] += eigen.eigenvectors()(j, k) * eigen.eigenvectors()(j, k);
    }
  }
  return share;
}

enum class Diagnosis {
  kLocal,  // each site's own block of J'J (its neighbours held): catches sites with too few samples
  kDense,  // the whole J'J: also finds deficiencies shared by several sites
};

// Sites carrying a share of the (near) null space. Empty if none is found, or (dense) the problem
// is too large to look.
std::vector<int> undetermined_sites(ceres::Problem& problem, std::vector<SiteBlock>& blocks,
                                    const std::vector<int>& sites, Diagnosis diagnosis) {
  std::vector<double*> order;
  std::vector<int> first_column;  // per entry of `sites`, then the total
  int columns = 0;
  for (int i : sites) {
    order.push_back(blocks[i].data());
    first_column.push_back(columns);
    columns += problem.ParameterBlockTangentSize(blocks[i].data());
  }
  first_column.push_back(columns);
  if (diagnosis == Diagnosis::kDense && columns > tolerance::kMaxDenseDiagnosisParameters) return {};
  std::vector<int> owner(columns);  // entry of `sites` per column
  for (std::size_t s = 0; s < sites.size(); ++s) {
    for (int j = first_column[s]; j < first_column[s + 1]; ++j) owner[j] = static_cast<int>(s);
  }
  ceres::Problem::EvaluateOptions evaluate;
  evaluate.parameter_blocks = order;
  ceres::CRSMatrix jacobian;
  if (!problem.Evaluate(evaluate, nullptr, nullptr, nullptr, &jacobian)) return {};

  std::vector<double> share(columns, 0.0);
  if (diagnosis == Diagnosis::kDense) {
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(columns, columns);
    for (int row = 0; row < jacobian.num_rows; ++row) {
      for (int p = jacobian.rows[row]; p < jacobian.rows[row + 1]; ++p) {
        for (int q = jacobian.rows[row]; q < jacobian.rows[row + 1]; ++q) {
          normal(jacobian.cols[p], jacobian.cols[q]) += jacobian.values[p] * jacobian.values[q];
        }
      }
    }
    share = null_space_shares(normal);
  } else {
    // One small block per site: the entries whose both columns belong to it.
    std::vector<Eigen::MatrixXd> local(sites.size());
    for (std::size_t s = 0; s < sites.size(); ++s) {
      const int size = first_column[s + 1] - first_column[s];
      local[s] = Eigen::MatrixXd::Zero(size, size);
    }
    for (int row = 0; row < jacobian.num_rows; ++row) {
      for (int p = jacobian.rows[row]; p < jacobian.rows[row + 1]; ++p) {
        for (int q = jacobian.rows[row]; q < jacobian.rows[row + 1]; ++q) {
          const int cp = jacobian.cols[p], cq = jacobian.cols[q];
          if (owner[cp] != owner[cq]) continue;
          const int base = first_column[owner[cp]];
          local[owner[cp]](cp - base, cq - base) += jacobian.values[p] * jacobian.values[q];
        }
      }
    }
    for (std::size_t s = 0; s < sites.size(); ++s) {
      const std::vector<double> local_share = null_space_shares(local[s]);
      for (std::size_t j = 0; j < local_share.size(); ++j) share[first_column[s] + j] = local_share[j];
    }
  }
  std::vector<int> undetermined;
  for (std::size_t s = 0; s < sites.size(); ++s) {
    double site_share = 0.0;
    for (int j = first_column[s]; j < first_column[s + 1]; ++j) site_share += share[j];
    if (site_share > tolerance::kNullSpaceShare) undetermined.push_back(sites[s]);
  }
  return undetermined;
}

void mark_undetermined(SiteUncertainty& u) {
  u.sigma_x = u.sigma_y = u.sigma_log_weight = kInfinity;
  u.cov_xy = 0.0;
  u.available = false;
}

}  // namespace

CovarianceOutcome site_covariance(std::vector<SiteBlock>& blocks, double* log_range, const SolvedProblem& solved,
                                  const RefineOptions& options) {
  const Layout& layout = solved.layout;
  const std::span<const BoundarySample> samples = solved.samples;
  const std::span<const double> r = solved.residuals;
  CovarianceOutcome outcome;
  outcome.uncertainty.resize(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (layout.group[i] != kNone) {
      outcome.uncertainty[i].log_weight_reference = layout.group_reference[layout.group[i]];
    }
  }
  std::vector<int> sites = observed_sites(layout);
  if (sites.empty()) return outcome;

  if (options.estimate_noise_scale) {
    const VarianceFactor kappa = estimate_variance_factor(options.loss, options.loss_scale, r, layout.free_parameters);
    if (!kappa.ok) {
      outcome.remark = kappa.problem;
      return outcome;
    }
    outcome.variance_factor = kappa.value;
  } else {
    outcome.variance_factor = model_variance_factor(options.loss, options.loss_scale);
  }
  std::vector<double> factor(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    factor[i] = std::sqrt(loss_at(solved.loss, r[i]).weight / outcome.variance_factor);
  }
  BuiltProblem built = build_problem(blocks, log_range, layout, samples, solved.priors, nullptr, factor);
  double* range = layout.range ? log_range : nullptr;

  // Full rank: done. Otherwise find the undetermined sites (cheap local test first, then the
  // dense one), hold them, and try again with the rest.
  std::size_t undetermined = 0;
  for (Diagnosis diagnosis : {Diagnosis::kLocal, Diagnosis::kDense}) {
    if (compute_blocks(*built.problem, blocks, sites, options.threads, outcome.uncertainty, range,
                       &outcome.log_range_sigma)) {
      if (undetermined > 0) {
        outcome.remark = "covariance: " + std::to_string(undetermined) + " site(s) undetermined by the data";
      }
      return outcome;
    }
    const std::vector<int> found = undetermined_sites(*built.problem, blocks, sites, diagnosis);
    for (int i : found) {
      mark_undetermined(outcome.uncertainty[i]);
      built.problem->SetParameterBlockConstant(blocks[i].data());
      std::erase(sites, i);
    }
    undetermined += found.size();
    if (sites.empty()) {
      outcome.remark = "covariance: " + std::to_string(undetermined) + " site(s) undetermined by the data (all)";
      return outcome;
    }
  }
  if (compute_blocks(*built.problem, blocks, sites, options.threads, outcome.uncertainty, range,
                     &outcome.log_range_sigma)) {
    outcome.remark = "covariance: " + std::to_string(undetermined) + " site(s) undetermined by the data";
    return outcome;
  }
  outcome.remark = "covariance: rank-deficient Jacobian" +
                   (undetermined > 0 ? ", " + std::to_string(undetermined) + " site(s) undetermined," : std::string()) +
                   " the rest not identified (problem too large for the dense check); no uncertainties for them";
  return outcome;
}

}  // namespace covmap::fitting::detail
