// covmap::io atomic output: a file either keeps its old content or gets the complete new content.
//
// write_file_atomically streams into a temporary file in the target's directory (same file system,
// so the final rename is atomic on POSIX), then renames it over the target. If `write` throws or
// the stream fails, the temporary is removed and the target is untouched; the exception propagates
// (stream failures become std::runtime_error naming the file). A reader never sees half a file.
// Not done: fsync. The guarantee holds against the process failing, not against power loss.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>

namespace covmap::io {

void write_file_atomically(const std::filesystem::path& target, const std::function<void(std::ostream&)>& write);

}  // namespace covmap::io
