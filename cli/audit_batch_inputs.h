// Which maps `covmap audit MAP... | FOLDER... -o OUTDIR/` audits, the sensors file of each, and the
// folder in OUTDIR its reports go to (README, "Batch audits"; docs/FORMATS.md, "Batch audits").
//
// Rules
//  - A file argument is a map, whatever its name. A folder argument gives every file directly in
//    it (not in its subfolders) whose name ends in a map extension (kMapExtensions, any case),
//    sorted by name; every other entry is skipped with its reason (SkippedFile). Arguments keep
//    their order; maps of one folder come together.
//  - One file argument is a single audit (MapList::batch false): reports directly in OUTDIR, as
//    before there were batches. Several arguments, or any folder, make a batch.
//  - Sensors: `--sensors S` is every map's. Without it, in a batch, the map DIR/STEM.EXT is audited
//    with DIR/STEM.sensors.X (X one of kSensorsExtensions) when that file exists; two such files
//    for one map are its failure (BatchMap::problem), not a guess. Files named STEM.sensors.X or
//    sensors.X in a folder are never taken for maps.
//  - Folders: a map's report folder is its file name without the last extension (STEM). Maps that
//    share a stem (compared ignoring case, as some file systems do) are each named PARENT_STEM,
//    PARENT being the name of the folder holding the map; a name still taken after that, or one
//    of the summaries' names, gets "-2", "-3", ... in the order of the maps. A name starting with
//    '.' (a hidden file's) gets a leading '_', since covmap's temporaries start with '.'.
//  - Rejected (io::InputError): an argument that is neither a readable file nor a folder, and
//    arguments that give no map at all (a folder without maps).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace covmap::cli {

inline constexpr std::array<std::string_view, 8> kMapExtensions = {".geojson", ".json", ".gpkg", ".shp",
                                                                   ".fgb",     ".tif",  ".tiff", ".kml"};
inline constexpr std::array<std::string_view, 7> kSensorsExtensions = {".csv", ".geojson", ".json", ".gpkg",
                                                                       ".shp", ".fgb",     ".kml"};
// The files a batch writes into OUTDIR beside the maps' folders.
inline constexpr std::string_view kSummaryCsv = "summary.csv";
inline constexpr std::string_view kSummaryJson = "summary.json";

// One map of the list.
struct BatchMap {
  std::string map;      // as typed, or FOLDER/NAME for a map found in a folder argument
  std::string sensors;  // --sensors, the map's own STEM.sensors.X, or empty
  std::string folder;   // its report folder's name in OUTDIR (batches only)
  std::string problem;  // non-empty: the map cannot be audited, and this is why
};

// Why an entry of a folder argument is not audited.
enum class SkipReason { kFolder, kHidden, kSensorsFile, kNotAMap };
// "folder", "hidden", "sensors_file", "not_a_map" (summary.json).
std::string_view to_string(SkipReason reason);
// The reason for people: "a folder (folders inside are not searched)", ...
std::string skip_reason_words(SkipReason reason);

struct SkippedFile {
  std::string file;  // FOLDER/NAME
  SkipReason reason = SkipReason::kNotAMap;
};

struct MapList {
  std::vector<BatchMap> maps;
  std::vector<SkippedFile> skipped;
  bool batch = false;  // several maps or a folder: OUTDIR/<folder>/ per map, plus the summaries
};

// The maps `arguments` name, as the rules above say. `sensors` is --sensors (empty: not given).
MapList list_maps(const std::vector<std::string>& arguments, const std::string& sensors);

}  // namespace covmap::cli
