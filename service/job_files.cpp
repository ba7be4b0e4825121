#include "service/job_files.h"

#include <cctype>

namespace covmap::service {

JobFiles job_files(const std::filesystem::path& data_dir, const std::string& id) {
  return JobFiles{data_dir / "jobs" / id};
}

std::filesystem::path job_store_file(const std::filesystem::path& data_dir) { return data_dir / "jobs.sqlite"; }

std::string safe_upload_name(const std::string& uploaded, const std::string& fallback) {
  std::string name = uploaded.substr(uploaded.find_last_of("/\\") == std::string::npos ? 0 : uploaded.find_last_of("/\\") + 1);
  for (char& c : name) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (!std::isalnum(u) && c != '.' && c != '-' && c != '_') c = '_';
  }
  while (!name.empty() && name.front() == '.') name.erase(0, 1);
  if (name.size() > 100) name = name.substr(name.size() - 100);
  if (name.empty() || name == "." || name == "..") return fallback;
  return name;
}

}  // namespace covmap::service
