#include "tools/mapgen/coverage_map_files.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "tools/mapgen/coverage_map_json.h"

namespace covmap::mapgen {
namespace {

// A name no other writer picks: hidden, unique per process and call.
std::filesystem::path temporary_dir(const std::filesystem::path& dir) {
  static std::atomic<unsigned> counter{0};
  static const unsigned salt = std::random_device{}();
  std::string name = ".covmap-make-map-tmp-";
  name += std::to_string(::getpid()) + "-" + std::to_string(salt) + "-" + std::to_string(counter++);
  return dir / name;
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot create '" + file.string() + "'");
  out << text;
  out.close();
  if (!out) throw std::runtime_error("error while writing '" + file.string() + "'");
}

}  // namespace

void write_coverage_map(const CoverageMap& map, const std::filesystem::path& dir) {
  // Render everything before touching the disk.
  const std::vector<std::pair<std::string, std::string>> files = {
      {kMapFileName, feature_collection_text(map_geojson(map))},
      {kSensorsFileName, feature_collection_text(sensors_geojson(map))},
      {kTruthFileName, truth_json(map).dump(1) + "\n"}};

  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create directory '" + dir.string() + "': " + ec.message());
  const std::filesystem::path temp = temporary_dir(dir);
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

}  // namespace covmap::mapgen
