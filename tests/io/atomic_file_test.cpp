#include "io/atomic_file.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <csignal>

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
  write_files_atomically({{dir / "out.txt", "hello\n"}});
  EXPECT_EQ(read_text(dir / "out.txt"), "hello\n");
  EXPECT_EQ(entries(dir.path()), 1u);
  write_files_atomically({{dir / "out.txt", "again\n"}});
  EXPECT_EQ(read_text(dir / "out.txt"), "again\n");
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicFile, CreatesMissingParentFolders) {
  TempDir dir;
  write_files_atomically({{dir / "no" / "such" / "out.txt", "x"}});
  EXPECT_EQ(read_text(dir / "no" / "such" / "out.txt"), "x");
}

TEST(AtomicFile, AFolderIsNeverReplacedByAFile) {
  TempDir dir;
  dir.write("keep/mine.txt", "precious");
  EXPECT_THROW(write_files_atomically({{dir / "keep", "x"}}), OutputError);
  EXPECT_EQ(read_text(dir / "keep" / "mine.txt"), "precious");
}

// All or nothing across files: the second output cannot be written (its place is a folder), so
// the first keeps its old content and no temporary is left anywhere.
TEST(AtomicFile, OneFailingOutputLeavesEveryOutputAsItWas) {
  TempDir dir;
  dir.write("a.json", "old a");
  dir.write("b.svg/inside.txt", "a folder where a file should go");
  EXPECT_THROW(write_files_atomically({{dir / "a.json", "new a"}, {dir / "b.svg", "new b"}}), OutputError);
  EXPECT_EQ(read_text(dir / "a.json"), "old a");
  EXPECT_EQ(entries(dir.path()), 2u);
}

// A full disk, simulated by a file-size limit (EFBIG is what ENOSPC looks like to a writer): the
// error is an OutputError naming the output and the system's reason; nothing is left behind.
TEST(AtomicFile, AFullDiskIsAnOutputErrorAndLeavesNothing) {
  TempDir dir;
  dir.write("out.txt", "old");
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old_limit{};
  getrlimit(RLIMIT_FSIZE, &old_limit);
  rlimit small = old_limit;
  small.rlim_cur = 1024;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    write_files_atomically({{dir / "out.txt", std::string(100000, 'x')}});
  } catch (const OutputError& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old_limit);
  EXPECT_NE(message.find("out.txt"), std::string::npos) << message;
  EXPECT_NE(message.find("too large"), std::string::npos) << message;
  EXPECT_EQ(read_text(dir / "out.txt"), "old");
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicFile, NewFolderAppearsComplete) {
  TempDir dir;
  write_new_folder_atomically(dir / "reports", {{"a.txt", "A"}, {"b.txt", "B"}});
  EXPECT_EQ(read_text(dir / "reports" / "a.txt"), "A");
  EXPECT_EQ(read_text(dir / "reports" / "b.txt"), "B");
  EXPECT_EQ(entries(dir.path()), 1u);
  EXPECT_THROW(write_new_folder_atomically(dir / "reports", {{"a.txt", "again"}}), OutputError);
  EXPECT_EQ(read_text(dir / "reports" / "a.txt"), "A");
}

}  // namespace
}  // namespace covmap::io
