// The small value-type members of refine.h: names of enums, option validation, the summary line.
#include <cmath>
#include <cstdio>

#include "fitting/refine.h"

namespace covmap::fitting {

std::string to_string(RobustLoss loss) {
  switch (loss) {
    case RobustLoss::kNone: return "none";
    case RobustLoss::kHuber: return "huber";
    case RobustLoss::kCauchy: return "cauchy";
  }
  return "unknown";
}

bool from_string(std::string_view name, RobustLoss* loss) {
  for (RobustLoss candidate : {RobustLoss::kNone, RobustLoss::kHuber, RobustLoss::kCauchy}) {
    if (name == to_string(candidate)) {
      *loss = candidate;
      return true;
    }
  }
  return false;
}

std::string to_string(SiteStatus status) {
  switch (status) {
    case SiteStatus::kRefined: return "refined";
    case SiteStatus::kFromPrior: return "from-prior";
    case SiteStatus::kUnobserved: return "unobserved";
  }
  return "unknown";
}

std::string to_string(Termination termination) {
  switch (termination) {
    case Termination::kNotRun: return "";
    case Termination::kConvergence: return "CONVERGENCE";
    case Termination::kNoConvergence: return "NO_CONVERGENCE";
    case Termination::kFailure: return "FAILURE";
    case Termination::kUserSuccess: return "USER_SUCCESS";
    case Termination::kUserFailure: return "USER_FAILURE";
    case Termination::kNoSamples: return "NO_SAMPLES";
    case Termination::kSettled: return "SETTLED";
  }
  return "unknown";
}

bool from_string(std::string_view name, Termination* termination) {
  for (Termination candidate : kAllTerminations) {
    if (name == to_string(candidate)) {
      *termination = candidate;
      return true;
    }
  }
  return false;
}

bool RefineOptions::IsValid(std::string* error) const {
  auto fail = [&](std::string message) {
    if (error != nullptr) *error = std::move(message);
    return false;
  };
  if (loss != RobustLoss::kNone && loss != RobustLoss::kHuber && loss != RobustLoss::kCauchy) {
    return fail("loss is not a RobustLoss value");
  }
  if (!std::isfinite(loss_scale) || !(loss_scale > 0)) {
    return fail("loss_scale must be finite and positive (got " + std::to_string(loss_scale) + ")");
  }
  if (!std::isfinite(function_tolerance) || !(function_tolerance > 0)) {
    return fail("function_tolerance must be finite and positive (got " + std::to_string(function_tolerance) + ")");
  }
  if (max_iterations < 1) return fail("max_iterations must be at least 1 (got " + std::to_string(max_iterations) + ")");
  if (threads < 1) return fail("threads must be at least 1 (got " + std::to_string(threads) + ")");
  if (held_range && !(std::isfinite(*held_range) && *held_range > 0))
    return fail("held_range must be finite and positive (got " + std::to_string(*held_range) + ")");
  if (settle) {
    const SettleRule& r = *settle;
    if (r.window < 1) return fail("settle.window must be at least 1 (got " + std::to_string(r.window) + ")");
    if (!(std::isfinite(r.position_step) && r.position_step > 0))
      return fail("settle.position_step must be finite and positive (got " + std::to_string(r.position_step) + ")");
    if (!(std::isfinite(r.log_weight_step) && r.log_weight_step > 0))
      return fail("settle.log_weight_step must be finite and positive (got " + std::to_string(r.log_weight_step) + ")");
    if (!(r.moving_share >= 0 && r.moving_share < 1))
      return fail("settle.moving_share must be in [0, 1) (got " + std::to_string(r.moving_share) + ")");
  }
  return true;
}

std::string RefineSummary::brief() const {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "%s after %d iterations, cost %.6g -> %.6g, rms %.6g over %zu samples",
                to_string(termination).c_str(), iterations, initial_cost, final_cost, rms_residual, samples);
  std::string line = buffer;
  if (sites_without_samples > 0) line += ", " + std::to_string(sites_without_samples) + " sites without samples";
  return line;
}

}  // namespace covmap::fitting
