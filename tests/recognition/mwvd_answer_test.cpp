// The MWVD answer's names: distinct, and read back as the same answer.
#include <gtest/gtest.h>

#include "recognition/recognize.h"

namespace covmap::recognition {
namespace {

TEST(MwvdAnswer, NamesReadBack) {
  for (MwvdAnswer a : {MwvdAnswer::kUnknown, MwvdAnswer::kYes, MwvdAnswer::kNo}) {
    const auto back = mwvd_answer_from_string(to_string(a));
    ASSERT_TRUE(back.has_value()) << to_string(a);
    EXPECT_EQ(*back, a);
  }
  EXPECT_EQ(to_string(MwvdAnswer::kYes), "yes");
  EXPECT_EQ(to_string(MwvdAnswer::kNo), "no");
  EXPECT_EQ(to_string(MwvdAnswer::kUnknown), "unknown");
  EXPECT_FALSE(mwvd_answer_from_string("maybe").has_value());
}

}  // namespace
}  // namespace covmap::recognition
