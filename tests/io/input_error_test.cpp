#include "io/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace covmap::io {
namespace {

TEST(InputError, OneProblemReadsFileLineItemMessage) {
  const InputError e("sites.csv", 7, "site 'b'", "weight must be positive (got -1)");
  EXPECT_STREQ(e.what(), "sites.csv:7: site 'b': weight must be positive (got -1)");
  EXPECT_EQ(e.file, "sites.csv");
  EXPECT_EQ(e.line(), 7);
  EXPECT_EQ(e.item(), "site 'b'");
  EXPECT_EQ(e.message(), "weight must be positive (got -1)");
}

TEST(InputError, EmptyPartsAreLeftOut) {
  EXPECT_STREQ(InputError("g.json", 0, "arcs[1].to", "bad").what(), "g.json: arcs[1].to: bad");
  EXPECT_STREQ(InputError("g.json", 0, "", "bad").what(), "g.json: bad");
  EXPECT_STREQ(InputError("", 0, "clip", "bad").what(), "clip: bad");
}

TEST(InputError, ManyProblemsAreListedUpToTheLimit) {
  std::vector<InputProblem> problems;
  for (int i = 1; i <= 25; ++i) problems.push_back({i, "site 'x'", "bad " + std::string(1, static_cast<char>('a' + i))});
  const InputError e("s.csv", problems);
  const std::string text = e.what();
  EXPECT_EQ(text.rfind("s.csv: 25 problems\n", 0), 0u) << text;
  EXPECT_NE(text.find("s.csv:20: site 'x': bad u"), std::string::npos);
  EXPECT_EQ(text.find("s.csv:21:"), std::string::npos);
  EXPECT_NE(text.find("... and 5 more"), std::string::npos);
  EXPECT_EQ(e.problems.size(), 25u);
}

// One mistake repeated on every feature is one line with a count, not 58 identical lines; the
// problems themselves are all kept.
TEST(InputError, ARepeatedMessageIsOneLineWithItsCount) {
  std::vector<InputProblem> problems;
  // Messages that differ only in their numbers are the same mistake.
  for (int i = 0; i < 58; ++i)
    problems.push_back({0, "features[" + std::to_string(i) + "]", "missing property (position " + std::to_string(i) + ")"});
  problems.push_back({0, "features[3]", "not closed"});
  const InputError e("map.geojson", problems);
  const std::string text = e.what();
  EXPECT_NE(text.find("map.geojson: 59 problems\n"), std::string::npos) << text;
  EXPECT_NE(text.find("features[0] (and 57 more like it): missing property (position 0)"), std::string::npos) << text;
  EXPECT_NE(text.find("features[3]: not closed"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << text;
  EXPECT_EQ(e.problems.size(), 59u);
}

}  // namespace
}  // namespace covmap::io
