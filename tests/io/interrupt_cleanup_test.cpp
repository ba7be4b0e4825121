// Interrupted runs clean up after themselves: each test forks a child that stands in
// for a covmap run, interrupts it with a real signal and inspects what is left on disk.
#include "io/interrupt_cleanup.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "io_test_util.h"

namespace covmap::io {
namespace {

using testing::TempDir;
namespace fs = std::filesystem;

// Runs `child` in a forked process and returns its wait status.
template <class F>
int in_child(F&& child) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    child();
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(InterruptCleanup, ASignalRemovesPendingFilesAndFoldersAndKillsTheProcess) {
  TempDir dir;
  const fs::path folder = dir / ".covmap-tmp-1-0-out";
  const int status = in_child([&] {
    install_interrupt_cleanup();
    fs::create_directory(folder);
    PendingPath folder_guard(folder);
    std::ofstream(folder / "report.json") << "half";
    PendingPath file_guard(folder / "report.json");
    std::ofstream(dir / "kept.txt") << "not registered";
    std::raise(SIGTERM);
    std::ofstream(dir / "after.txt") << "never reached";
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_FALSE(fs::exists(folder));
  EXPECT_TRUE(fs::exists(dir / "kept.txt"));
  EXPECT_FALSE(fs::exists(dir / "after.txt"));
}

TEST(InterruptCleanup, ASignalInACriticalSectionWaitsForItsEnd) {
  TempDir dir;
  const int status = in_child([&] {
    install_interrupt_cleanup();
    const fs::path temp = dir / "temp";
    std::ofstream(temp) << "x";
    PendingPath guard(temp);
    {
      CriticalSection section;
      std::raise(SIGINT);
      std::ofstream(dir / "finished.txt") << "the section ran to its end";
    }
    std::ofstream(dir / "after.txt") << "never reached";
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
  EXPECT_TRUE(fs::exists(dir / "finished.txt"));
  EXPECT_FALSE(fs::exists(dir / "temp"));
  EXPECT_FALSE(fs::exists(dir / "after.txt"));
}

TEST(InterruptCleanup, AReleasedPathIsLeftAlone) {
  TempDir dir;
  const int status = in_child([&] {
    install_interrupt_cleanup();
    std::ofstream(dir / "done.json") << "complete";
    { PendingPath guard(dir / "done.json"); }  // renamed into place: no longer pending
    std::raise(SIGTERM);
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_TRUE(fs::exists(dir / "done.json"));
}

}  // namespace
}  // namespace covmap::io
