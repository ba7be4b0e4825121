// Helpers shared by the service tests: a scratch folder for a database, and jobs to store.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <string>

#include "service/job.h"

namespace covmap::service::testing {

// A new folder (mkdtemp) under the system temp dir, removed with its content at the end.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "covmap-service-test-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) ADD_FAILURE() << "mkdtemp failed for " << pattern;
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  std::filesystem::path database() const { return path_ / "jobs.sqlite"; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
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
