#include "service/job.h"

#include <chrono>
#include <cstdio>
#include <random>

namespace covmap::service {
namespace {

// A job id: 128 bits, written as hexadecimal digits.
constexpr std::size_t kJobIdBits = 128;
constexpr std::size_t kJobIdLength = kJobIdBits / 4;

}  // namespace

std::string_view job_status_name(JobStatus status) {
  switch (status) {
    case JobStatus::kQueued: return "queued";
    case JobStatus::kRunning: return "running";
    case JobStatus::kDone: return "done";
    case JobStatus::kFailed: return "failed";
    case JobStatus::kCancelled: return "cancelled";
  }
  return "unknown";  // not reached: every enumerator is handled above
}

std::optional<JobStatus> job_status_from_name(std::string_view name) {
  for (const JobStatus status : kAllJobStatuses) {
    if (job_status_name(status) == name) return status;
  }
  return std::nullopt;
}

bool is_finished(JobStatus status) {
  switch (status) {
    case JobStatus::kQueued:
    case JobStatus::kRunning: return false;
    case JobStatus::kDone:
    case JobStatus::kFailed:
    case JobStatus::kCancelled: return true;
  }
  return false;  // not reached
}

std::string new_job_id() {
  std::random_device random;
  // random_device yields unsigned ints; take 32 bits of each, 8 hex digits at a time.
  using Word = std::uint32_t;
  constexpr std::size_t kDigitsPerWord = sizeof(Word) * 2;
  std::string id;
  id.reserve(kJobIdLength);
  char digits[kDigitsPerWord + 1];
  while (id.size() < kJobIdLength) {
    std::snprintf(digits, sizeof digits, "%08x", static_cast<unsigned>(static_cast<Word>(random())));
    id += digits;
  }
  return id;
}

bool is_valid_job_id(std::string_view id) {
  if (id.size() != kJobIdLength) return false;
  for (const char c : id) {
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

std::int64_t unix_now_ms() {
  using namespace std::chrono;
  return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

}  // namespace covmap::service
