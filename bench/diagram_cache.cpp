#include "bench/diagram_cache.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <type_traits>

namespace covmap::bench {
namespace {

static_assert(std::is_trivially_copyable_v<Node>);
static_assert(std::is_trivially_copyable_v<Arc>);

// Changes with the layout of Node and Arc, so that a cache from another build is not misread.
constexpr std::uint64_t kMagic = 0xc0fe'0000'0000'0000ULL | (sizeof(Node) << 16) | sizeof(Arc);

template <class T>
void write_vector(std::ofstream& out, const std::vector<T>& v) {
  const std::uint64_t n = v.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
}

template <class T>
bool read_vector(std::ifstream& in, std::vector<T>& v) {
  std::uint64_t n = 0;
  if (!in.read(reinterpret_cast<char*>(&n), sizeof n)) return false;
  v.resize(n);
  return static_cast<bool>(in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T))));
}

}  // namespace

void save_graph(const Diagram& d, const std::string& path) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(&kMagic), sizeof kMagic);
    write_vector(out, d.nodes);
    write_vector(out, d.arcs);
    if (!out) return;
  }
  std::filesystem::rename(tmp, path);
}

std::optional<Diagram> load_graph(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t magic = 0;
  if (!in || !in.read(reinterpret_cast<char*>(&magic), sizeof magic) || magic != kMagic) return std::nullopt;
  Diagram d;
  if (!read_vector(in, d.nodes) || !read_vector(in, d.arcs)) return std::nullopt;
  return d;
}

}  // namespace covmap::bench
