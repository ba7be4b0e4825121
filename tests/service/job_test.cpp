#include "service/job.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace covmap::service {
namespace {

// The names of the API (docs/openapi.json), written out here rather than taken from the code.
const std::vector<std::pair<JobStatus, std::string>> kExpectedNames = {
    {JobStatus::kQueued, "queued"},
    {JobStatus::kRunning, "running"},
    {JobStatus::kDone, "done"},
    {JobStatus::kFailed, "failed"},
    {JobStatus::kCancelled, "cancelled"},
};

TEST(JobStatus, EveryStatusHasItsNameBothWays) {
  ASSERT_EQ(kExpectedNames.size(), kAllJobStatuses.size());
  for (const auto& [status, name] : kExpectedNames) {
    EXPECT_EQ(job_status_name(status), name);
    EXPECT_EQ(job_status_from_name(name), status) << name;
  }
}

TEST(JobStatus, OtherNamesAreNotStatuses) {
  for (const std::string name : {"", "Queued", "DONE", "queued ", "canceled", "finished", "unknown"}) {
    EXPECT_EQ(job_status_from_name(name), std::nullopt) << "'" << name << "'";
  }
}

TEST(JobStatus, OnlyDoneFailedAndCancelledAreFinished) {
  EXPECT_FALSE(is_finished(JobStatus::kQueued));
  EXPECT_FALSE(is_finished(JobStatus::kRunning));
  EXPECT_TRUE(is_finished(JobStatus::kDone));
  EXPECT_TRUE(is_finished(JobStatus::kFailed));
  EXPECT_TRUE(is_finished(JobStatus::kCancelled));
}

TEST(JobId, NewIdsAreValidLowercaseHexAndDistinct) {
  constexpr int kIds = 2000;
  std::set<std::string> seen;
  for (int i = 0; i < kIds; ++i) {
    const std::string id = new_job_id();
    ASSERT_EQ(id.size(), 32u) << id;
    EXPECT_EQ(id.find_first_not_of("0123456789abcdef"), std::string::npos) << id;
    EXPECT_TRUE(is_valid_job_id(id)) << id;
    seen.insert(id);
  }
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(kIds));
}

// All 16 digits turn up: the ids are not, say, decimal digits or a constant pattern.
TEST(JobId, NewIdsUseEveryHexDigit) {
  std::set<char> digits;
  for (int i = 0; i < 100; ++i) {
    for (const char c : new_job_id()) digits.insert(c);
  }
  EXPECT_EQ(digits.size(), 16u);
}

TEST(JobId, PathTraversalAndOtherShapesAreRejected) {
  const std::string good = "0123456789abcdef0123456789abcdef";
  ASSERT_TRUE(is_valid_job_id(good));
  std::string upper = good;
  upper[10] = 'A';
  for (const std::string& bad : {std::string("../etc/passwd"), std::string("../../../../../../../../etc/pass"),
                                 upper, good.substr(1), good + "0", std::string(), good.substr(0, 31) + "g",
                                 good.substr(0, 31) + "/", good.substr(0, 31) + std::string(1, '\0'),
                                 std::string("..") + good.substr(2)}) {
    EXPECT_FALSE(is_valid_job_id(bad)) << "'" << bad << "'";
  }
}

}  // namespace
}  // namespace covmap::service
