#include "service/serve_options.h"

namespace covmap::service {

bool ServeOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (host.empty()) return fail("host must not be empty");
  if (port < 0 || port > 65535) return fail("port must be in 0-65535");
  if (data_dir.empty()) return fail("data folder must not be empty");
  if (workers < 1 || workers > 64) return fail("workers must be in 1-64");
  if (queue_limit < 1) return fail("queue limit must be at least 1");
  if (max_upload_mb < 1 || max_upload_mb > 4096) return fail("max upload must be in 1-4096 MiB");
  if (max_sync_mb < 1) return fail("max synchronous body must be at least 1 MiB");
  if (job_cpu_seconds < 1) return fail("job CPU time must be at least 1 s");
  if (job_memory_mb < 64) return fail("job memory must be at least 64 MiB");
  if (max_attempts < 1) return fail("max attempts must be at least 1");
  return true;
}

}  // namespace covmap::service
