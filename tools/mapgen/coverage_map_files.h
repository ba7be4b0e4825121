// covmap::mapgen files: write a generated coverage map as map.geojson, sensors.geojson and
// truth.json into a directory.
//
// Contract: the directory is created if needed. All three documents are rendered and written into a
// fresh hidden temporary directory inside it first; only when all three are complete are they
// renamed into place, one rename per file (atomic on POSIX, same file system). On any failure the
// temporary directory is removed, the exception propagates (std::runtime_error naming the path) and
// files already in `dir` are untouched — unless the failure strikes between two of the three final
// renames, the only window in which a reader could see a mix of old and new files. Not done: fsync.
#pragma once

#include <filesystem>

#include "tools/mapgen/coverage_map_generator.h"

namespace covmap::mapgen {

inline constexpr const char* kMapFileName = "map.geojson";
inline constexpr const char* kSensorsFileName = "sensors.geojson";
inline constexpr const char* kTruthFileName = "truth.json";

void write_coverage_map(const CoverageMap& map, const std::filesystem::path& dir);

}  // namespace covmap::mapgen
