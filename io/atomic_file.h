// covmap::io atomic output: a file either keeps its old content or gets the complete new content.
//
// write_file_atomically streams into a temporary file in the target's directory (same file system,
// so the final rename is atomic on POSIX), then renames it over the target. If `write` throws or
// the stream fails, the temporary is removed and the target is untouched; the exception propagates
// (stream failures become std::runtime_error naming the file). A reader never sees half a file.
//
// Several files at once, all rendered in memory first (a name and its complete text each):
// - write_directory_atomically makes `target` a directory holding exactly `files`: they are written
//   into a fresh directory beside it, which then takes the target's place (an existing target is
//   renamed aside first and removed after). A failure before the swap leaves the target untouched
//   and removes the fresh directory.
// - write_files_into_directory puts `files` into the existing or new directory `dir`, leaving its
//   other files alone: all are written into a hidden temporary directory inside `dir` first, then
//   each is renamed over its target. A failure while writing leaves `dir` as it was.
// Not done: fsync. The guarantee holds against the process failing, not against power loss.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace covmap::io {

void write_file_atomically(const std::filesystem::path& target, const std::function<void(std::ostream&)>& write);

// File names (no folders) and their complete contents.
using NamedTexts = std::vector<std::pair<std::string, std::string>>;

void write_directory_atomically(const std::filesystem::path& target, const NamedTexts& files);
void write_files_into_directory(const std::filesystem::path& dir, const NamedTexts& files,
                                const std::string& temporary_prefix);

}  // namespace covmap::io
