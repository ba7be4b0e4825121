// covmap::io output plans: what a command will write, checked before it does any work, so that
// nothing the user did not ask to replace is ever destroyed.
//
// Rules (check_output_plan throws OutputError naming the output and what to do instead):
// - No output may be one of the inputs (compared by file identity when both exist, by absolute
//   path otherwise), no file a report folder will hold may be an input, and no two outputs may be
//   the same.
// - A file output must not be an existing folder; a folder output must not be an existing file.
// - A folder output (a report folder) may be new, empty, or a folder covmap wrote (it holds the
//   marker kFolderMarker, which lists the files covmap put there). Any other existing folder is
//   refused unless `force`; with `force` covmap writes its files into it and leaves every other
//   file alone.
// - Paths are taken as given: relative paths, "." and trailing slashes work ("out/" is "out").
//
// write_report_folder (or ReportFolderWriter, file by file) then writes the folder all or nothing
// (io/atomic_file.h): a new folder appears complete in one rename; in an existing folder the
// files (and the marker) are replaced together, and files an earlier run listed in the marker but
// this run does not write are removed. Before writing, remove_stale_temporaries clears leftovers of covmap runs that were
// killed (SIGKILL, power loss): hidden ".covmap-tmp-<pid>-..." entries whose process no longer
// exists, and the "NAME.tmp-N" / "NAME.old-N" report folders older versions left, when they hold
// nothing but covmap's report files.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/atomic_file.h"

namespace covmap::io {

inline constexpr const char* kFolderMarker = ".covmap-output";

struct OutputPlan {
  std::vector<std::filesystem::path> inputs;
  std::vector<std::filesystem::path> files;        // single-file outputs (-o FILE, --svg)
  std::optional<std::filesystem::path> folder;      // a report folder (-o DIR)
  std::vector<std::string> folder_files;            // the names written into it
  bool force = false;                               // write into a folder covmap did not make
};

// "out/" -> "out", "./a//b" -> "a/b", "." stays "."; empty stays empty.
std::filesystem::path normalized_output_path(const std::filesystem::path& path);

void check_output_plan(const OutputPlan& plan);

// Writes `files` plus the marker into `folder` as described above. Re-checks the folder rules.
void write_report_folder(const std::filesystem::path& folder, NamedTexts files, bool force);

// The same, file by file: each file is written through a stream as soon as it is ready (nothing
// held in memory), and commit() puts the folder in place all or nothing. The constructor re-checks
// the folder rules; destroyed without commit(), nothing of the run is left. add() may be called
// from several threads at once.
class ReportFolderWriter {
 public:
  ReportFolderWriter(const std::filesystem::path& folder, bool force);
  void add(const std::string& name, const StreamWriter& write);
  void add(const std::string& name, std::string text);
  void commit();

 private:
  std::filesystem::path folder_;
  bool existing_ = false;
  std::vector<std::string> names_;
  std::mutex names_mutex_;
  std::unique_ptr<StagedFolder> new_folder_;  // a new folder: written aside, renamed into place
  std::unique_ptr<StagedFiles> into_folder_;  // an existing one: its files replaced together
};

// Removes covmap's leftovers in `dir` (not recursive); returns how many entries were removed.
int remove_stale_temporaries(const std::filesystem::path& dir);

}  // namespace covmap::io
