// Helpers shared by the service tests: a scratch folder for a database, and jobs to store.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "service/job.h"
#include "tests/support/temp_dir.h"

namespace covmap::service::testing {

// A scratch folder (tests/support/temp_dir.h) holding a job database.
class ScratchFolder : public covmap::testing::TempDir {
 public:
  std::filesystem::path database() const { return path() / "jobs.sqlite"; }
};

// A queued job as the server submits it, created at `created_ms`.
inline Job queued_job(std::int64_t created_ms) {
  Job job;
  job.id = new_job_id();
  job.created_ms = created_ms;
  job.options_json = R"({"alpha": 3.5})";
  job.map_name = "map.geojson";
  return job;
}

}  // namespace covmap::service::testing
