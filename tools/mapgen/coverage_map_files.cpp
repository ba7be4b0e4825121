#include "tools/mapgen/coverage_map_files.h"

#include <string>
#include <utility>
#include <vector>

#include "io/atomic_file.h"
#include "tools/mapgen/coverage_map_json.h"

namespace covmap::mapgen {

void write_coverage_map(const CoverageMap& map, const std::filesystem::path& dir) {
  // Render everything before touching the disk.
  const io::NamedTexts files = {
      {kMapFileName, feature_collection_text(map_geojson(map))},
      {kSensorsFileName, feature_collection_text(sensors_geojson(map))},
      {kTruthFileName, truth_json(map).dump(1) + "\n"}};

  io::write_files_into_directory(dir, files);
}

}  // namespace covmap::mapgen
