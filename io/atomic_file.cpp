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

}  // namespace

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
