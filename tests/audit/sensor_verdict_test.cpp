// Verdict names: every verdict has its own name, and the name reads back as the same verdict.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "audit/sensor_verdict.h"

namespace covmap::audit {
namespace {

TEST(SensorVerdict, NamesAreDistinctAndReadBack) {
  std::set<std::string> names;
  for (SensorVerdict v : kAllSensorVerdicts) {
    const std::string name(to_string(v));
    EXPECT_TRUE(names.insert(name).second) << "two verdicts named " << name;
    ASSERT_TRUE(sensor_verdict_from_string(name).has_value()) << name;
    EXPECT_EQ(*sensor_verdict_from_string(name), v) << name;
  }
  EXPECT_EQ(names.size(), std::size(kAllSensorVerdicts));
}

TEST(SensorVerdict, TheReportsNamesAreTheDocumentedOnes) {
  // docs/FORMATS.md, report.json: "consistent", "inconsistent", "undetermined", "not_in_map".
  EXPECT_EQ(sensor_verdict_from_string("consistent"), SensorVerdict::kConsistent);
  EXPECT_EQ(sensor_verdict_from_string("inconsistent"), SensorVerdict::kInconsistent);
  EXPECT_EQ(sensor_verdict_from_string("undetermined"), SensorVerdict::kUndetermined);
  EXPECT_EQ(sensor_verdict_from_string("not_in_map"), SensorVerdict::kNotInMap);
  EXPECT_FALSE(sensor_verdict_from_string("").has_value());
  EXPECT_FALSE(sensor_verdict_from_string("other").has_value());
  EXPECT_FALSE(sensor_verdict_from_string("Consistent").has_value());
}

}  // namespace
}  // namespace covmap::audit
