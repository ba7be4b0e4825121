// Judging one reported sensor against the one the map implies. The reconstruction and
// the report are two estimates of the same (x, y, log w); their difference, measured in the sum of
// both covariances plus model floors, is a Mahalanobis distance² that is χ²-distributed with 3
// degrees of freedom (2 when no strength was reported) when the report is right. The report is
// "inconsistent" above the threshold: the map is then explained significantly better by the
// reconstructed values than by the reported ones (to first order this is the likelihood-ratio
// test of fixing the sensor at its reported values, without refitting once per sensor).
#pragma once

#include <optional>
#include <string>

#include "audit/audit.h"

namespace covmap::audit {

struct VerdictInput {
  double dx = 0.0, dy = 0.0;          // reported − reconstructed position
  std::optional<double> dlogw;        // reported − reconstructed log weight (common factor removed)
  double var_x = 0.0, var_y = 0.0, cov_xy = 0.0, var_logw = 0.0;  // reconstruction (1-σ²)
  double reported_position_sigma = 0.0;                           // stated, metres
  std::optional<double> reported_logw_sigma;                      // stated, in log weight
  double position_floor = 0.0;        // metres
  double logw_floor = 0.0;            // log weight
  std::optional<double> alpha;        // to state log-weight differences in dB
};

struct Judgement {
  double chi2 = 0.0;
  int dof = 0;
  bool inconsistent = false;
  std::string reason;
};

// threshold3: the χ² threshold for 3 degrees of freedom; the 2-dof threshold is the same
// probability's quantile (computed from it).
Judgement judge(const VerdictInput& in, double threshold3);

// The probability that χ² with `dof` (2 or 3) degrees of freedom exceeds x.
double chi2_tail(double x, int dof);

// The 2-degree-of-freedom threshold with the same tail probability as threshold3 for 3.
double chi2_quantile_two_dof(double threshold3);

}  // namespace covmap::audit
