#include "io/atomic_file.h"

#include <gtest/gtest.h>

#include <ostream>
#include <stdexcept>

#include "io_test_util.h"

namespace covmap::io {
namespace {

using testing::read_text;
using testing::TempDir;

std::size_t entries(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()));
}

TEST(AtomicFile, WritesAndLeavesNoTemporary) {
  TempDir dir;
  write_file_atomically(dir / "out.txt", [](std::ostream& out) { out << "hello\n"; });
  EXPECT_EQ(read_text(dir / "out.txt"), "hello\n");
  EXPECT_EQ(entries(dir.path()), 1u);
  write_file_atomically(dir / "out.txt", [](std::ostream& out) { out << "again\n"; });
  EXPECT_EQ(read_text(dir / "out.txt"), "again\n");
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicFile, FailureKeepsTheOldFileAndRemovesTheTemporary) {
  TempDir dir;
  dir.write("out.txt", "old\n");
  EXPECT_THROW(write_file_atomically(dir / "out.txt",
                                     [](std::ostream& out) {
                                       out << "half of the new";
                                       throw std::runtime_error("writer failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read_text(dir / "out.txt"), "old\n");
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicFile, MissingDirectoryThrows) {
  TempDir dir;
  EXPECT_THROW(write_file_atomically(dir / "no" / "such" / "out.txt", [](std::ostream& out) { out << "x"; }),
               std::runtime_error);
  EXPECT_EQ(entries(dir.path()), 0u);
}

}  // namespace
}  // namespace covmap::io
