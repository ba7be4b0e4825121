// The box type against hand-computed bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/box.h"

namespace covmap {
namespace {

TEST(Box, StartsEmptyAndGrowsFromTheFirstPoint) {
  Box b;
  EXPECT_TRUE(b.empty());
  EXPECT_FALSE(b.finite());
  EXPECT_EQ(b.diagonal(), 0.0);
  b.add(Point{3, -1});
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.xmin, 3);
  EXPECT_EQ(b.xmax, 3);
  b.add(-1, 2);
  EXPECT_EQ(b.xmin, -1);
  EXPECT_EQ(b.ymin, -1);
  EXPECT_EQ(b.xmax, 3);
  EXPECT_EQ(b.ymax, 2);
  EXPECT_DOUBLE_EQ(b.diagonal(), 5.0);
  EXPECT_EQ(b.centre().x, 1.0);
  EXPECT_EQ(b.centre().y, 0.5);
}

TEST(Box, AddFiniteSkipsRaysAndNaN) {
  Box b;
  b.add_finite(std::numeric_limits<double>::infinity(), 0);
  b.add_finite(0, std::nan(""));
  EXPECT_TRUE(b.empty());
  b.add_finite(1, 1);
  EXPECT_TRUE(b.finite());
  Box c;
  c.add(std::numeric_limits<double>::infinity(), 0);
  EXPECT_FALSE(c.finite());
}

TEST(Box, ContainsOverlapsAndGrows) {
  const Box b{0, 0, 2, 1};
  EXPECT_TRUE(b.contains({2, 1}));   // closed
  EXPECT_FALSE(b.contains({2.5, 0.5}));
  EXPECT_TRUE(b.overlaps(Box{2, 1, 3, 3}));  // touching counts
  EXPECT_FALSE(b.overlaps(Box{2.1, 0, 3, 1}));
  EXPECT_FALSE(b.overlaps(Box{}));   // nothing overlaps an empty box
  const Box g = b.grown(0.5);
  EXPECT_EQ(g.xmin, -0.5);
  EXPECT_EQ(g.ymax, 1.5);
  Box u = b;
  u.add_box(Box{-1, 5, 0, 6});
  EXPECT_EQ(u.xmin, -1);
  EXPECT_EQ(u.ymax, 6);
  EXPECT_EQ(u.width(), 3);
  EXPECT_EQ(u.height(), 6);
}

}  // namespace
}  // namespace covmap
