#include "io/atomic_file.h"

#include <atomic>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <unistd.h>

namespace covmap::io {
namespace {

// A name no other writer picks: same directory, hidden, unique per process and call.
std::filesystem::path temporary_name(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  static const unsigned salt = std::random_device{}();
  // Built by appending: GCC 12 gives a false -Wrestrict for "literal" + std::string (PR 105651).
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(salt) + "-" + std::to_string(counter++);
  return target.parent_path() / name;
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot create '" + file.string() + "'");
  out << text;
  out.close();
  if (!out) throw std::runtime_error("error while writing '" + file.string() + "'");
}

// A hidden name in `dir` no other writer picks: unique per process and call.
std::filesystem::path temporary_dir(const std::filesystem::path& dir, const std::string& prefix) {
  static std::atomic<unsigned> counter{0};
  static const unsigned salt = std::random_device{}();
  std::string name = prefix;
  name += std::to_string(::getpid()) + "-" + std::to_string(salt) + "-" + std::to_string(counter++);
  return dir / name;
}

}  // namespace

void write_directory_atomically(const std::filesystem::path& target, const NamedTexts& files) {
  namespace fs = std::filesystem;
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  fs::create_directories(parent);
  std::random_device rd;
  const fs::path temp = parent / (target.filename().string() + ".tmp-" + std::to_string(rd()));
  try {
    fs::create_directory(temp);
    for (const auto& [name, content] : files) {
      std::ofstream f(temp / name, std::ios::binary);
      f << content;
      f.close();
      if (!f) throw std::runtime_error("cannot write " + (temp / name).string());
    }
    if (fs::exists(target)) {
      const fs::path old = parent / (target.filename().string() + ".old-" + std::to_string(rd()));
      fs::rename(target, old);
      fs::rename(temp, target);
      fs::remove_all(old);
    } else {
      fs::rename(temp, target);
    }
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(temp, ignored);
    throw;
  }
}

void write_files_into_directory(const std::filesystem::path& dir, const NamedTexts& files,
                                const std::string& temporary_prefix) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create directory '" + dir.string() + "': " + ec.message());
  const std::filesystem::path temp = temporary_dir(dir, temporary_prefix);
  try {
    if (!std::filesystem::create_directory(temp, ec) || ec)
      throw std::runtime_error("cannot create '" + temp.string() + "': " + ec.message());
    for (const auto& [name, text] : files) write_text(temp / name, text);
    for (const auto& [name, text] : files) {
      std::filesystem::rename(temp / name, dir / name, ec);
      if (ec) throw std::runtime_error("cannot replace '" + (dir / name).string() + "': " + ec.message());
    }
    std::filesystem::remove(temp, ec);
  } catch (...) {
    std::error_code ignored;  // the original failure is the one worth reporting
    std::filesystem::remove_all(temp, ignored);
    throw;
  }
}

void write_file_atomically(const std::filesystem::path& target, const std::function<void(std::ostream&)>& write) {
  if (target.filename().empty()) throw std::invalid_argument("write_file_atomically: '" + target.string() + "' names no file");
  const std::filesystem::path temp = temporary_name(target);
  try {
    {
      std::ofstream out(temp, std::ios::binary | std::ios::trunc);
      if (!out) throw std::runtime_error("cannot create '" + temp.string() + "' to write '" + target.string() + "'");
      write(out);
      out.flush();
      if (!out) throw std::runtime_error("error while writing '" + target.string() + "'");
      out.close();
      if (!out) throw std::runtime_error("error while closing '" + target.string() + "'");
    }
    std::error_code ec;
    std::filesystem::rename(temp, target, ec);
    if (ec) throw std::runtime_error("cannot replace '" + target.string() + "': " + ec.message());
  } catch (...) {
    std::error_code ignored;  // the original failure is the one worth reporting
    std::filesystem::remove(temp, ignored);
    throw;
  }
}

}  // namespace covmap::io
