#include "io/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <memory>
#include <system_error>
#include <unistd.h>

#include "io/interrupt_cleanup.h"

namespace covmap::io {
namespace fs = std::filesystem;
namespace {

std::string errno_text(int err) { return std::strerror(err); }

void make_parent_folder(const fs::path& target) {
  const fs::path parent = target.parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  if (fs::is_directory(parent, ec)) return;
  fs::create_directories(parent, ec);
  if (ec) throw OutputError(target, "cannot create the folder '" + parent.string() + "': " + ec.message());
}

fs::path folder_of(const fs::path& target) { return target.has_parent_path() ? target.parent_path() : fs::path("."); }

}  // namespace

// One output on its way: the temporary holding the new text, and the old version's backup link.
struct Staged {
  fs::path target, temp, backup;
  std::unique_ptr<PendingPath> temp_guard, backup_guard;
  bool replaced = false;
  bool had_old = false;
};

namespace {

// Writes a new file (which must not exist) through a stream; failures name the output and the
// system's reason.
void write_new_file_streamed(const fs::path& file, const StreamWriter& write, const fs::path& shown_as) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw OutputError(shown_as, "cannot create a file in '" + file.parent_path().string() + "': " + errno_text(errno));
  ::close(fd);
  std::vector<char> buffer(1 << 20);
  std::ofstream out;
  out.rdbuf()->pubsetbuf(buffer.data(), static_cast<std::streamsize>(buffer.size()));
  out.open(file, std::ios::binary | std::ios::trunc);
  if (!out) throw OutputError(shown_as, "cannot open its temporary for writing: " + errno_text(errno));
  errno = 0;
  write(out);
  out.flush();
  if (!out) throw OutputError(shown_as, "error while writing: " + errno_text(errno ? errno : EIO));
  out.close();
  if (!out) throw OutputError(shown_as, "error while writing: " + errno_text(errno ? errno : EIO));
}

// Puts every staged file in place, or puts every target back as it was and throws.
void swap_into_place(std::vector<Staged>& staged) {
  CriticalSection no_interrupts;
  std::size_t k = 0;
  try {
    for (; k < staged.size(); ++k) {
      Staged& s = staged[k];
      std::error_code ec;
      s.had_old = fs::exists(fs::symlink_status(s.target, ec));
      if (s.had_old) {
        s.backup_guard = std::make_unique<PendingPath>(s.backup);
        fs::create_hard_link(s.target, s.backup, ec);  // no backup (e.g. FAT): no rollback for it
        if (ec) s.backup.clear();
      }
      fs::rename(s.temp, s.target, ec);
      if (ec) throw OutputError(s.target, "cannot replace it: " + ec.message());
      s.replaced = true;
    }
  } catch (...) {
    for (std::size_t j = 0; j < k; ++j) {
      std::error_code ignored;
      if (!staged[j].backup.empty()) fs::rename(staged[j].backup, staged[j].target, ignored);
      else if (!staged[j].had_old) fs::remove(staged[j].target, ignored);
    }
    throw;
  }
  for (Staged& s : staged) {
    std::error_code ignored;
    if (!s.backup.empty()) fs::remove(s.backup, ignored);
  }
}

}  // namespace

OutputError::OutputError(const fs::path& output, const std::string& reason)
    : std::runtime_error("cannot write '" + output.string() + "': " + reason), output_(output) {}

std::string temporary_name(const std::string& target_name) {
  static std::atomic<unsigned> counter{0};
  std::string name = kTemporaryPrefix;
  name += std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" + target_name;
  return name;
}

// The in-memory forms: the staged classes below with each text written in one piece.
void write_files_atomically(const std::vector<FileText>& files) {
  StagedFiles staged;
  for (const FileText& f : files)
    staged.stage(f.path, [&f](std::ostream& out) { out.write(f.text.data(), static_cast<std::streamsize>(f.text.size())); });
  staged.commit();
}

void write_new_folder_atomically(const fs::path& folder, const NamedTexts& files) {
  StagedFolder staged(folder);
  for (const auto& entry : files) {
    // A named reference, not a structured binding: clang 14 cannot capture bindings.
    const std::string& text = entry.second;
    staged.stage(entry.first, [&text](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
  }
  staged.commit();
}

StagedFiles::StagedFiles() = default;

StagedFiles::~StagedFiles() {
  if (committed_) return;
  for (const auto& s : staged_) {
    std::error_code ignored;
    fs::remove(s->temp, ignored);
  }
}

void StagedFiles::stage(const fs::path& target, const StreamWriter& write) {
  if (!target.has_filename()) throw OutputError(target, "it names a folder, not a file");
  std::error_code ec;
  if (fs::is_directory(target, ec)) throw OutputError(target, "it is a folder; give a file name");
  Staged* s = nullptr;
  {
    std::lock_guard lock(mutex_);
    make_parent_folder(target);
    staged_.push_back(std::make_unique<Staged>());
    s = staged_.back().get();
    s->target = target;
    s->temp = folder_of(target) / temporary_name(target.filename().string());
    s->backup = folder_of(target) / temporary_name(target.filename().string() + ".old");
    s->temp_guard = std::make_unique<PendingPath>(s->temp);
  }
  write_new_file_streamed(s->temp, write, target);
}

void StagedFiles::commit() {
  std::vector<Staged> all;
  for (auto& s : staged_) all.push_back(std::move(*s));
  staged_.clear();
  try {
    swap_into_place(all);
  } catch (...) {
    for (Staged& s : all) {
      std::error_code ignored;
      if (!s.replaced) fs::remove(s.temp, ignored);
    }
    committed_ = true;  // nothing of ours is left to remove
    throw;
  }
  committed_ = true;
}

StagedFolder::StagedFolder(const fs::path& folder) : folder_(folder) {
  make_parent_folder(folder);
  temp_ = folder_of(folder) / temporary_name(folder.filename().string());
  guards_.push_back(std::make_unique<PendingPath>(temp_));
  std::error_code ec;
  if (!fs::create_directory(temp_, ec) || ec)
    throw OutputError(folder, "cannot create a folder in '" + folder_of(folder).string() + "': " + ec.message());
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(temp_, ignored);
}

void StagedFolder::stage(const std::string& name, const StreamWriter& write) {
  {
    std::lock_guard lock(mutex_);
    guards_.push_back(std::make_unique<PendingPath>(temp_ / name));
  }
  write_new_file_streamed(temp_ / name, write, folder_ / name);
}

void StagedFolder::commit() {
  CriticalSection no_interrupts;
  std::error_code ec;
  if (fs::exists(folder_, ec)) throw OutputError(folder_, "it appeared while covmap was writing; nothing was replaced");
  fs::rename(temp_, folder_, ec);
  if (ec) throw OutputError(folder_, "cannot move the finished folder into place: " + ec.message());
  committed_ = true;
}

void write_files_into_directory(const fs::path& dir, const NamedTexts& files) {
  std::vector<FileText> texts;
  for (const auto& [name, text] : files) texts.push_back({dir / name, text});
  write_files_atomically(texts);
}

}  // namespace covmap::io
