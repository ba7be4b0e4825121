#include "fitting/solver_logging.h"

#include <glog/logging.h>

#include <mutex>

namespace covmap::fitting::detail {

void quiet_solver_logging() {
  static std::once_flag once;
  std::call_once(once, [] { FLAGS_minloglevel = google::GLOG_FATAL; });
}

}  // namespace covmap::fitting::detail
