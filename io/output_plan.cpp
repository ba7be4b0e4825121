#include "io/output_plan.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <fstream>
#include <set>
#include <sstream>

namespace covmap::io {
namespace fs = std::filesystem;
namespace {

constexpr const char* kMarkerTitle = "covmap report folder; covmap wrote the files listed below";
// The files older covmap versions wrote into NAME.tmp-N / NAME.old-N beside a report folder.
const std::set<std::string> kLegacyReportFiles = {"report.json", "report.html", "sensors.geojson", "diagram.geojson"};

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) {
    const bool same = fs::equivalent(a, b, ec);
    if (!ec) return same;
  }
  return fs::weakly_canonical(fs::absolute(a), ec) == fs::weakly_canonical(fs::absolute(b), ec);
}

bool is_temporary(const std::string& name) { return name.rfind(kTemporaryPrefix, 0) == 0; }

enum class FolderState { kMissing, kNotAFolder, kEmpty, kCovmaps, kForeign };

struct FolderLook {
  FolderState state = FolderState::kMissing;
  std::vector<std::string> names;  // what is in it, temporaries left out, sorted
};

FolderLook look_at(const fs::path& folder) {
  FolderLook look;
  std::error_code ec;
  const fs::file_status status = fs::status(folder, ec);
  if (!fs::exists(status)) return look;
  if (!fs::is_directory(status)) {
    look.state = FolderState::kNotAFolder;
    return look;
  }
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!is_temporary(name)) look.names.push_back(name);
  }
  if (ec) throw OutputError(folder, "cannot list the folder: " + ec.message());
  std::sort(look.names.begin(), look.names.end());
  const bool marked = std::binary_search(look.names.begin(), look.names.end(), std::string(kFolderMarker));
  look.state = look.names.empty() ? FolderState::kEmpty : marked ? FolderState::kCovmaps : FolderState::kForeign;
  return look;
}

std::string listing(const std::vector<std::string>& names) {
  std::string text;
  const std::size_t shown = std::min<std::size_t>(names.size(), 3);
  for (std::size_t k = 0; k < shown; ++k) text += (k ? ", " : "") + names[k];
  if (names.size() > shown) text += " and " + std::to_string(names.size() - shown) + " more";
  return text;
}

// What is in `folder`, once the rules allow writing there.
FolderLook checked_folder(const fs::path& folder, bool force) {
  const FolderLook look = look_at(folder);
  if (look.state == FolderState::kNotAFolder)
    throw OutputError(folder, "it is a file, and covmap writes a folder of reports here; give a folder name");
  if (look.state == FolderState::kForeign && !force)
    throw OutputError(folder, "the folder holds files covmap did not write (" + listing(look.names) +
                                  "); give a new or empty folder, or pass --force to write covmap's files into it "
                                  "(other files are left alone)");
  return look;
}

std::vector<std::string> marker_listing(const fs::path& folder) {
  std::ifstream in(folder / kFolderMarker);
  std::vector<std::string> names;
  std::string line;
  if (!std::getline(in, line) || line != kMarkerTitle) return names;
  while (std::getline(in, line))
    if (!line.empty() && line.find('/') == std::string::npos && line != "." && line != "..") names.push_back(line);
  return names;
}

bool process_is_gone(long pid) {
  if (pid <= 0) return false;
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// ".covmap-tmp-<pid>-...": the pid, or -1.
long temporary_owner(const std::string& name) {
  const std::size_t start = std::string(kTemporaryPrefix).size();
  std::size_t end = start;
  while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
  if (end == start || end >= name.size() || name[end] != '-') return -1;
  return std::stol(name.substr(start, end - start));
}

// "NAME.tmp-123" or "NAME.old-123" holding only report files.
bool is_legacy_report_leftover(const fs::directory_entry& entry) {
  const std::string name = entry.path().filename().string();
  std::size_t dot = name.rfind('.');
  if (dot == std::string::npos || dot == 0) return false;
  const std::string tail = name.substr(dot + 1);
  if (tail.rfind("tmp-", 0) != 0 && tail.rfind("old-", 0) != 0) return false;
  if (tail.size() == 4 || !std::all_of(tail.begin() + 4, tail.end(), [](unsigned char c) { return std::isdigit(c); }))
    return false;
  std::error_code ec;
  if (!entry.is_directory(ec)) return false;
  for (fs::directory_iterator it(entry.path(), ec), end; !ec && it != end; it.increment(ec))
    if (!kLegacyReportFiles.count(it->path().filename().string()) || !it->is_regular_file(ec)) return false;
  return !ec;
}

}  // namespace

fs::path normalized_output_path(const fs::path& path) {
  if (path.empty()) return path;
  fs::path p = path.lexically_normal();
  if (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p.empty() ? fs::path(".") : p;
}

void check_output_plan(const OutputPlan& plan) {
  std::vector<fs::path> outputs;
  for (const fs::path& f : plan.files) {
    const fs::path p = normalized_output_path(f);
    std::error_code ec;
    if (fs::is_directory(p, ec) || !p.has_filename() || p.filename() == "." || p.filename() == "..")
      throw OutputError(p, "it is a folder; give a file name");
    outputs.push_back(p);
  }
  if (plan.folder) {
    const fs::path folder = normalized_output_path(*plan.folder);
    checked_folder(folder, plan.force);
    for (const std::string& name : plan.folder_files) outputs.push_back(folder / name);
    for (const fs::path& input : plan.inputs)
      if (same_file(input, folder)) throw OutputError(folder, "it is one of the inputs; give another folder");
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (const fs::path& input : plan.inputs)
      if (same_file(input, outputs[i]))
        throw OutputError(outputs[i], "it is the input '" + input.string() + "'; covmap never writes over its inputs");
    for (std::size_t j = 0; j < i; ++j)
      if (same_file(outputs[i], outputs[j])) throw OutputError(outputs[i], "two outputs are the same file");
  }
}

ReportFolderWriter::ReportFolderWriter(const fs::path& given, bool force) : folder_(normalized_output_path(given)) {
  if (folder_.has_parent_path()) remove_stale_temporaries(folder_.parent_path());
  else remove_stale_temporaries(".");
  const FolderLook look = checked_folder(folder_, force);
  existing_ = look.state != FolderState::kMissing;
  if (existing_) {
    remove_stale_temporaries(folder_);
    into_folder_ = std::make_unique<StagedFiles>();
  } else {
    new_folder_ = std::make_unique<StagedFolder>(folder_);
  }
}

void ReportFolderWriter::add(const std::string& name, const StreamWriter& write) {
  {
    std::lock_guard lock(names_mutex_);
    names_.push_back(name);
  }
  if (existing_) into_folder_->stage(folder_ / name, write);
  else new_folder_->stage(name, write);
}

void ReportFolderWriter::add(const std::string& name, std::string text) {
  add(name, [&text](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

void ReportFolderWriter::commit() {
  std::ostringstream marker;
  marker << kMarkerTitle << "\n";
  std::vector<std::string> names = names_;  // added from several threads: listed in a fixed order
  std::sort(names.begin(), names.end());
  for (const std::string& name : names) marker << name << "\n";
  const std::string marker_text = marker.str();
  const StreamWriter write_marker = [&marker_text](std::ostream& out) { out << marker_text; };
  if (!existing_) {
    new_folder_->stage(kFolderMarker, write_marker);
    new_folder_->commit();
    return;
  }
  const std::vector<std::string> earlier = marker_listing(folder_);
  into_folder_->stage(folder_ / kFolderMarker, write_marker);
  into_folder_->commit();
  for (const std::string& name : earlier) {
    if (std::find(names_.begin(), names_.end(), name) != names_.end()) continue;
    std::error_code ignored;
    if (fs::is_regular_file(folder_ / name, ignored)) fs::remove(folder_ / name, ignored);
  }
}

void write_report_folder(const fs::path& given, NamedTexts files, bool force) {
  ReportFolderWriter writer(given, force);
  for (auto& [name, text] : files) {
    writer.add(name, std::move(text));
    std::string().swap(text);
  }
  writer.commit();
}

int remove_stale_temporaries(const fs::path& dir) {
  int removed = 0;
  std::error_code ec;
  std::vector<fs::path> doomed;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if ((is_temporary(name) && process_is_gone(temporary_owner(name))) || is_legacy_report_leftover(*it))
      doomed.push_back(it->path());
  }
  for (const fs::path& p : doomed) {
    std::error_code ignored;
    if (fs::remove_all(p, ignored) > 0) ++removed;
  }
  return removed;
}

}  // namespace covmap::io
