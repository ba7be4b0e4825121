// covmap::service job folders: where a job's uploads and reports live under --data.
//
//   DATA/jobs.sqlite            the job store (service/job_store.h)
//   DATA/jobs/ID/input/NAME     the uploaded map and sensors, under safe names keeping the extension
//   DATA/jobs/ID/out/           the reports the audit writes
//   DATA/jobs/ID/request.json   the job's audit request (job/audit_request_json.h)
//   DATA/jobs/ID/outcome.json   how the job's process ended the audit (job/audit_outcome.h)
//   DATA/jobs/ID/stdout.txt     the audit's summary lines
// IDs are checked (is_valid_job_id) before any path is made of them, so no request can name a
// file outside DATA.
#pragma once

#include <filesystem>
#include <string>

namespace covmap::service {

struct JobFiles {
  std::filesystem::path dir;  // DATA/jobs/ID

  std::filesystem::path input_dir() const { return dir / "input"; }
  std::filesystem::path output_dir() const { return dir / "out"; }
  std::filesystem::path stdout_file() const { return dir / "stdout.txt"; }
  std::filesystem::path request_file() const { return dir / "request.json"; }
  std::filesystem::path outcome_file() const { return dir / "outcome.json"; }
};

JobFiles job_files(const std::filesystem::path& data_dir, const std::string& id);
std::filesystem::path job_store_file(const std::filesystem::path& data_dir);

// An uploaded file's name made safe to store: its last path component, letters, digits, '.', '-'
// and '_' only (others become '_'), no leading dot, at most 100 characters, the extension kept (it
// tells the readers what the file is); `fallback` ("map", "sensors") when nothing is left.
std::string safe_upload_name(const std::string& uploaded, const std::string& fallback);

}  // namespace covmap::service
