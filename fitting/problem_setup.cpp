#include "fitting/problem_setup.h"

#include "fitting/boundary_group_cost.h"

#include <cmath>
#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

#include <ceres/manifold.h>

namespace covmap::fitting::detail {
namespace {

// Union-find over site indices.
class Groups {
 public:
  explicit Groups(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(int a, int b) { parent_[find(a)] = find(b); }

 private:
  std::vector<int> parent_;
};

}  // namespace

Layout make_layout(std::span<const Site> initial, std::span<const BoundarySample> samples,
                   std::span<const SitePrior> priors) {
  const std::size_t n = initial.size();
  Layout layout;
  layout.sample_count.assign(n, 0);
  layout.group.assign(n, kNone);
  Groups groups(n);
  int first_range_site = kNone;  // the common R joins every site with a range edge into one group
  for (const BoundarySample& s : samples) {
    ++layout.sample_count[s.site_a];
    if (s.site_b == kNone) {
      layout.range = true;
      if (first_range_site == kNone) first_range_site = s.site_a;
      groups.join(s.site_a, first_range_site);
      continue;
    }
    ++layout.sample_count[s.site_b];
    groups.join(s.site_a, s.site_b);
  }
  std::vector<int> group_of_root(n, kNone);
  for (std::size_t i = 0; i < n; ++i) {
    if (layout.sample_count[i] == 0) continue;
    int& g = group_of_root[groups.find(static_cast<int>(i))];
    if (g == kNone) {
      g = static_cast<int>(layout.group_reference.size());
      layout.group_reference.push_back(static_cast<int>(i));
    }
    layout.group[i] = g;
    // Reference: the largest initial weight of the group (first such site on ties).
    if (initial[i].weight > initial[layout.group_reference[g]].weight) layout.group_reference[g] = static_cast<int>(i);
  }
  std::vector<bool> weight_prior(layout.group_reference.size(), false);
  for (const SitePrior& p : priors) {
    if (p.log_weight_sigma > 0 && layout.group[p.site] != kNone) weight_prior[layout.group[p.site]] = true;
  }
  std::size_t observed = 0;
  for (std::size_t i = 0; i < n; ++i) observed += layout.sample_count[i] > 0 ? 1 : 0;
  layout.free_parameters = kSiteBlockSize * observed + (layout.range ? 1 : 0);
  for (std::size_t g = 0; g < weight_prior.size(); ++g) {
    if (weight_prior[g]) {
      layout.group_reference[g] = kNone;
    } else {
      --layout.free_parameters;
    }
  }
  return layout;
}

std::vector<SiteBlock> initial_blocks(std::span<const Site> initial) {
  std::vector<SiteBlock> blocks;
  blocks.reserve(initial.size());
  for (const Site& s : initial) blocks.push_back({s.x, s.y, std::log(s.weight)});
  return blocks;
}

BuiltProblem build_problem(std::vector<SiteBlock>& blocks, double* log_range, const Layout& layout,
                           std::span<const BoundarySample> samples, std::span<const SitePrior> priors,
                           ceres::LossFunction* loss, std::span<const double> sample_factor) {
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  BuiltProblem built;
  built.problem = std::make_unique<ceres::Problem>(problem_options);
  ceres::Problem& problem = *built.problem;
  // Blocks in site order, so the covariance and diagnostics see a stable column order.
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (layout.sample_count[i] > 0) problem.AddParameterBlock(blocks[i].data(), kSiteBlockSize);
  }
  if (layout.range) problem.AddParameterBlock(log_range, 1);
  if (layout.range && layout.hold_range) problem.SetParameterBlockConstant(log_range);
  built.sample_blocks.resize(samples.size());
  // Under a loss, a pair's boundary samples form one block (boundary_group_cost.h); without one
  // (the covariance problem) each sample is its own.
  std::map<std::pair<int, int>, std::size_t> pair_of;
  std::vector<std::vector<std::size_t>> pairs;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const BoundarySample& s = samples[i];
    const double factor = sample_factor.empty() ? 1.0 : sample_factor[i];
    if (s.site_b == kNone) {
      built.sample_blocks[i] = problem.AddResidualBlock(RangeResidual::Create(s.p.x, s.p.y, factor / s.sigma), loss,
                                                        blocks[s.site_a].data(), log_range);
    } else if (loss == nullptr) {
      built.sample_blocks[i] = problem.AddResidualBlock(BoundaryResidual::Create(s.p.x, s.p.y, factor / s.sigma),
                                                        nullptr, blocks[s.site_a].data(), blocks[s.site_b].data());
    } else {
      const auto [at, added] = pair_of.try_emplace({s.site_a, s.site_b}, pairs.size());
      if (added) pairs.emplace_back();
      pairs[at->second].push_back(i);
    }
  }
  for (const std::vector<std::size_t>& members : pairs) {
    std::vector<PairSample> points;
    points.reserve(members.size());
    for (std::size_t i : members) {
      const double factor = sample_factor.empty() ? 1.0 : sample_factor[i];
      points.push_back({samples[i].p.x, samples[i].p.y, factor / samples[i].sigma});
    }
    auto* cost = new PairCost(std::move(points), loss);
    built.pair_losses.push_back(std::make_unique<PairLoss>(cost));
    const BoundarySample& first = samples[members.front()];
    const ceres::ResidualBlockId id = problem.AddResidualBlock(cost, built.pair_losses.back().get(),
                                                               blocks[first.site_a].data(), blocks[first.site_b].data());
    for (std::size_t i : members) built.sample_blocks[i] = id;
  }
  for (const SitePrior& p : priors) {
    if (layout.sample_count[p.site] == 0) continue;  // unobserved sites are set from priors directly
    if (p.position_sigma > 0) {
      problem.AddResidualBlock(PositionPriorResidual::Create(p.position.x, p.position.y, p.position_sigma), nullptr,
                               blocks[p.site].data());
    }
    if (p.log_weight_sigma > 0) {
      problem.AddResidualBlock(LogWeightPriorResidual::Create(p.log_weight, p.log_weight_sigma), nullptr,
                               blocks[p.site].data());
    }
  }
  std::vector<char> is_reference(blocks.size(), 0);
  for (int reference : layout.group_reference) {
    if (reference == kNone) continue;
    is_reference[reference] = 1;
    problem.SetManifold(blocks[reference].data(), new ceres::SubsetManifold(kSiteBlockSize, {kLogWeightIndex}));
  }
  // A log weight wandering tens of units away (a weight ratio beyond 1e13) only happens on the
  // way to a divergence from a bad start; bounding it keeps the residuals finite there.
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (layout.sample_count[i] == 0 || is_reference[i]) continue;
    problem.SetParameterLowerBound(blocks[i].data(), kLogWeightIndex, blocks[i][kLogWeightIndex] - tolerance::kLogWeightExcursion);
    problem.SetParameterUpperBound(blocks[i].data(), kLogWeightIndex, blocks[i][kLogWeightIndex] + tolerance::kLogWeightExcursion);
  }
  return built;
}

double geometric_residual(const std::vector<SiteBlock>& blocks, double log_range, const BoundarySample& sample) {
  double r = 0.0;
  if (sample.site_b == kNone) {
    RangeResidual(sample.p.x, sample.p.y, 1.0)(blocks[sample.site_a].data(), &log_range, &r);
  } else {
    BoundaryResidual(sample.p.x, sample.p.y, 1.0)(blocks[sample.site_a].data(), blocks[sample.site_b].data(), &r);
  }
  return r;
}

double initial_log_range(const std::vector<SiteBlock>& blocks, std::span<const BoundarySample> samples) {
  std::vector<double> logs;
  for (const BoundarySample& s : samples) {
    if (s.site_b != kNone) continue;
    const SiteBlock& a = blocks[s.site_a];
    const double d = std::hypot(s.p.x - a[0], s.p.y - a[1]);
    if (d > 0) logs.push_back(std::log(d) - a[kLogWeightIndex]);
  }
  if (logs.empty()) return 0.0;
  std::nth_element(logs.begin(), logs.begin() + logs.size() / 2, logs.end());
  return logs[logs.size() / 2];
}

}  // namespace covmap::fitting::detail
