#include "cli/audit_batch_inputs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>

#include "io/input_error.h"

namespace covmap::cli {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kSensorsInfix = ".sensors";  // STEM.sensors.X
constexpr std::string_view kSensorsStem = "sensors";    // sensors.X

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

bool has_extension_in(const fs::path& file, const auto& extensions) {
  const std::string extension = lower(file.extension().string());
  return std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
}

// ".geojson, .json, ..., .kml"
std::string map_extensions_text() {
  std::string text;
  for (const std::string_view extension : kMapExtensions) text += (text.empty() ? "" : ", ") + std::string(extension);
  return text;
}

// "bern.sensors.geojson", "sensors.csv": a sensors file by the batch's convention.
bool is_sensors_file(const fs::path& file) {
  if (!has_extension_in(file, kSensorsExtensions)) return false;
  const std::string stem = lower(file.stem().string());
  return stem == kSensorsStem ||
         (stem.size() > kSensorsInfix.size() && stem.ends_with(kSensorsInfix));
}

// Every entry of the folder: the maps, sorted by name, and the rest with why it is skipped.
void list_folder(const fs::path& folder, MapList& list) {
  std::vector<fs::path> entries;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) entries.push_back(it->path());
  if (ec) throw io::InputError(folder.string(), 0, "", "cannot list the folder: " + ec.message());
  std::sort(entries.begin(), entries.end(),
            [](const fs::path& a, const fs::path& b) { return a.filename().string() < b.filename().string(); });
  for (const fs::path& entry : entries) {
    const std::string name = entry.filename().string();
    std::error_code status_error;
    if (fs::is_directory(entry, status_error)) list.skipped.push_back({entry.string(), SkipReason::kFolder});
    else if (name.starts_with(".")) list.skipped.push_back({entry.string(), SkipReason::kHidden});
    else if (is_sensors_file(entry)) list.skipped.push_back({entry.string(), SkipReason::kSensorsFile});
    else if (!has_extension_in(entry, kMapExtensions)) list.skipped.push_back({entry.string(), SkipReason::kNotAMap});
    else list.maps.push_back({entry.string(), "", "", ""});
  }
}

// DIR/STEM.sensors.X beside the map, or a problem when there are several.
void find_own_sensors(BatchMap& map) {
  const fs::path path(map.map);
  std::vector<std::string> found;
  for (const std::string_view extension : kSensorsExtensions) {
    fs::path candidate = path;
    candidate.replace_filename(path.stem().string() + std::string(kSensorsInfix) + std::string(extension));
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) found.push_back(candidate.string());
  }
  if (found.size() == 1) map.sensors = found.front();
  if (found.size() > 1) {
    map.problem = "the map has several sensors files (";
    for (std::size_t k = 0; k < found.size(); ++k) map.problem += (k ? ", " : "") + found[k];
    map.problem += "); keep one of them, or give the sensors of every map with --sensors";
  }
}

// The rules of the header: STEM, then PARENT_STEM for shared stems, then a counter.
void name_folders(std::vector<BatchMap>& maps) {
  std::vector<std::string> names;
  std::map<std::string, int> uses;
  for (const BatchMap& m : maps) {
    std::string stem = fs::path(m.map).stem().string();
    if (stem.empty() || stem.starts_with(".")) stem = "_" + stem;
    names.push_back(stem);
    ++uses[lower(stem)];
  }
  for (std::size_t i = 0; i < maps.size(); ++i) {
    if (uses[lower(names[i])] < 2) continue;
    std::error_code ec;
    const std::string parent = fs::absolute(fs::path(maps[i].map), ec).parent_path().filename().string();
    if (!parent.empty()) names[i] = parent + "_" + names[i];
  }
  std::set<std::string> taken = {lower(std::string(kSummaryCsv)), lower(std::string(kSummaryJson))};
  for (std::size_t i = 0; i < maps.size(); ++i) {
    std::string name = names[i];
    for (int k = 2; taken.count(lower(name)); ++k) name = names[i] + "-" + std::to_string(k);
    taken.insert(lower(name));
    maps[i].folder = name;
  }
}

}  // namespace

std::string_view to_string(SkipReason reason) {
  switch (reason) {
    case SkipReason::kFolder: return "folder";
    case SkipReason::kHidden: return "hidden";
    case SkipReason::kSensorsFile: return "sensors_file";
    case SkipReason::kNotAMap: return "not_a_map";
  }
  return "not_a_map";
}

std::string skip_reason_words(SkipReason reason) {
  switch (reason) {
    case SkipReason::kFolder: return "a folder (folders inside are not searched)";
    case SkipReason::kHidden: return "a hidden file";
    case SkipReason::kSensorsFile: return "a sensors file (STEM.sensors.* is read with the map STEM, sensors.* is not a map)";
    case SkipReason::kNotAMap: return "not a map (maps end in " + map_extensions_text() + ")";
  }
  return "";
}

MapList list_maps(const std::vector<std::string>& arguments, const std::string& sensors) {
  MapList list;
  bool any_folder = false;
  for (const std::string& argument : arguments) {
    std::error_code ec;
    const fs::file_status status = fs::status(argument, ec);
    if (fs::is_directory(status)) {
      any_folder = true;
      const std::size_t before = list.maps.size();
      list_folder(argument, list);
      if (list.maps.size() == before)
        throw io::InputError(argument, 0, "", "the folder holds no map (files ending in " + map_extensions_text() + ")");
    } else if (fs::is_regular_file(status)) {
      list.maps.push_back({argument, "", "", ""});
    } else {
      throw io::InputError(argument, 0, "", "neither a map file nor a folder of maps");
    }
  }
  list.batch = any_folder || list.maps.size() > 1;
  for (BatchMap& m : list.maps) {
    if (!sensors.empty()) m.sensors = sensors;
    else if (list.batch) find_own_sensors(m);
  }
  if (list.batch) name_folders(list.maps);
  return list;
}

}  // namespace covmap::cli
