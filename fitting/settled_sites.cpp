#include "fitting/settled_sites.h"

#include <cmath>

#include "fitting/residuals.h"

namespace covmap::fitting::detail {

SettledSites::SettledSites(const std::vector<SiteBlock>& blocks, const SettleRule& rule)
    : blocks_(blocks), rule_(rule), before_(blocks) {}

ceres::CallbackReturnType SettledSites::operator()(const ceres::IterationSummary& summary) {
  // Only steps that moved the sites count: a run of rejected steps (the trust region shrinking)
  // leaves every site where it was without the map having settled.
  if (summary.iteration == 0 || !summary.step_is_successful) return ceres::SOLVER_CONTINUE;
  if (++steps_ % rule_.window != 0) return ceres::SOLVER_CONTINUE;
  moving_ = 0;
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const SiteBlock& now = blocks_[i];
    const SiteBlock& then = before_[i];
    const bool moved = std::hypot(now[0] - then[0], now[1] - then[1]) > rule_.position_step ||
                       std::abs(now[kLogWeightIndex] - then[kLogWeightIndex]) > rule_.log_weight_step;
    if (moved) ++moving_;
  }
  before_ = blocks_;
  settled_ = static_cast<double>(moving_) <= rule_.moving_share * static_cast<double>(blocks_.size());
  return settled_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
}

}  // namespace covmap::fitting::detail
