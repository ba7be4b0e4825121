// Ceres reports through glog (for example rank-deficient covariances). covmap states what matters
// in its own results (RefineSummary, the audit's messages), so fitting keeps glog quiet below
// FATAL: a program that links covmap keeps stderr for its own messages. Internal to fitting.
#pragma once

namespace covmap::fitting::detail {

// Sets glog's threshold once per process, before the first solve; later calls do nothing.
void quiet_solver_logging();

}  // namespace covmap::fitting::detail
