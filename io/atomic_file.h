// covmap::io atomic output: several files replaced together, or none of them.
//
// Everything is rendered in memory first; these functions only put complete texts in place.
// - write_files_atomically: each text is written to a hidden temporary beside its target (same
//   folder, so renaming is atomic on POSIX), and only when all are complete are they renamed over
//   their targets, inside an io::CriticalSection so an interrupt cannot stop half-way. The old
//   version of each replaced target is kept as a hard link until all renames succeeded, so a
//   failing rename puts every earlier target back. A failure anywhere leaves every target as it
//   was and no temporary behind. Missing parent folders are created.
// - write_new_folder_atomically: `folder` must not exist; the files are written into a hidden
//   temporary folder beside it which is then renamed to `folder` in one step.
// - write_files_into_directory: write_files_atomically for files in one (possibly new) folder.
// - StagedFiles / StagedFolder: the same two guarantees for outputs too large to hold in memory
//   (a large audit's reports are hundreds of MB): each file is written through a stream straight into
//   its temporary as soon as it is ready, and commit() puts them all in place as above. Destroyed
//   without commit() (an exception while rendering), they remove every temporary. stage() may be
//   called from several threads at once.
// Temporaries are named ".covmap-tmp-<pid>-<n>-<name>" and registered with io::PendingPath, so
// SIGINT/SIGTERM remove them; after a SIGKILL, remove_stale_temporaries (output_plan.h) does.
// Failures throw OutputError naming the output and the system's reason ("No space left on
// device", "Permission denied", "File too large"): an output covmap cannot write is the user's
// to fix, not an internal error.
// Not done: fsync. The guarantee holds against the process failing, not against power loss.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace covmap::io {

class PendingPath;  // io/interrupt_cleanup.h

class OutputError : public std::runtime_error {
 public:
  OutputError(const std::filesystem::path& output, const std::string& reason);
  const std::filesystem::path& output() const { return output_; }

 private:
  std::filesystem::path output_;
};

struct FileText {
  std::filesystem::path path;
  std::string text;
};

// File names (no folders) and their complete contents.
using NamedTexts = std::vector<std::pair<std::string, std::string>>;

// Writes one file's content to `out`; an exception abandons the whole output.
using StreamWriter = std::function<void(std::ostream& out)>;

struct Staged;

// Files replaced together (write_files_atomically, file by file).
class StagedFiles {
 public:
  StagedFiles();
  ~StagedFiles();
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  void stage(const std::filesystem::path& target, const StreamWriter& write);
  void commit();

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<Staged>> staged_;
  bool committed_ = false;
};

// A new folder written file by file (write_new_folder_atomically); `folder` must not exist.
class StagedFolder {
 public:
  explicit StagedFolder(const std::filesystem::path& folder);
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;
  void stage(const std::string& name, const StreamWriter& write);
  void commit();

 private:
  std::filesystem::path folder_, temp_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<PendingPath>> guards_;
  bool committed_ = false;
};

void write_files_atomically(const std::vector<FileText>& files);
void write_new_folder_atomically(const std::filesystem::path& folder, const NamedTexts& files);
void write_files_into_directory(const std::filesystem::path& dir, const NamedTexts& files);

// The prefix of every temporary name, and the name for (this process, a counter, a target name).
inline constexpr const char* kTemporaryPrefix = ".covmap-tmp-";
std::string temporary_name(const std::string& target_name);

}  // namespace covmap::io
