// The iteration callback behind RefineOptions::settle (refine.h): it compares the sites every
// `window` successful iterations and ends the solve once no more than the rule's share of them
// still moves.
// Internal to fitting/.
#pragma once

#include <cstddef>
#include <vector>

#include <ceres/iteration_callback.h>

#include "fitting/problem_setup.h"
#include "fitting/refine.h"

namespace covmap::fitting::detail {

class SettledSites : public ceres::IterationCallback {
 public:
  // `blocks` are the solver's parameter blocks, which Ceres must write back after every iteration
  // (Solver::Options::update_state_every_iteration).
  SettledSites(const std::vector<SiteBlock>& blocks, const SettleRule& rule);
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override;

  bool settled() const { return settled_; }
  // The sites that moved more than the rule's steps over the last window compared.
  std::size_t still_moving() const { return moving_; }

 private:
  const std::vector<SiteBlock>& blocks_;
  SettleRule rule_;
  std::vector<SiteBlock> before_;  // the sites at the last checked iteration
  std::size_t moving_ = 0;
  int steps_ = 0;  // successful iterations so far
  bool settled_ = false;
};

}  // namespace covmap::fitting::detail
