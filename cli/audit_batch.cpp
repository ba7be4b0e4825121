#include "cli/audit_batch.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/audit_batch_summary.h"
#include "cli/audit_summary.h"
#include "cli/cli_support.h"
#include "io/input_error.h"
#include "io/output_plan.h"

namespace covmap::cli {
namespace fs = std::filesystem;
namespace {

std::vector<fs::path> all_inputs(const AuditCommandOptions& options, const MapList& list) {
  std::vector<fs::path> inputs(options.inputs.begin(), options.inputs.end());  // maps and folders as typed
  for (const BatchMap& m : list.maps) {
    inputs.push_back(m.map);
    if (!m.sensors.empty()) inputs.push_back(m.sensors);
  }
  return inputs;
}

fs::path map_folder(const AuditCommandOptions& options, const BatchMap& m) {
  return io::normalized_output_path(options.request.outputs.folder.string()) / m.folder;
}

// Every output of the batch, before any work (header: a refusal writes nothing).
void check_outputs(const AuditCommandOptions& options, const MapList& list) {
  io::OutputPlan batch;
  batch.inputs = all_inputs(options, list);
  batch.folder = options.request.outputs.folder;
  batch.folder_files = {std::string(kSummaryCsv), std::string(kSummaryJson)};
  for (const BatchMap& m : list.maps) batch.folder_files.push_back(m.folder);
  batch.force = options.request.settings.force;
  io::check_output_plan(batch);
  for (const BatchMap& m : list.maps) {
    io::OutputPlan own = batch;
    own.folder = map_folder(options, m);
    own.folder_files = report::audit_report_file_names(options.request.outputs.format);
    io::check_output_plan(own);
  }
}

// A new OUTDIR, or one holding nothing but temporaries, is made covmap's (its marker, no files)
// before the maps' folders go in: else a killed batch would leave folders without a marker, which
// the next run could only write into with --force. A marked OUTDIR is left for the summaries.
void mark_output_folder(const AuditCommandOptions& options) {
  const fs::path folder = io::normalized_output_path(options.request.outputs.folder.string());
  std::error_code ec;
  if (fs::exists(folder / io::kFolderMarker, ec)) return;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (!it->path().filename().string().starts_with(io::kTemporaryPrefix)) return;  // --force: left as it is
  io::write_report_folder(folder, {}, options.request.settings.force);
}

struct MapRun {
  MapOutcome outcome;
  int exit_code = kOk;  // what this map alone would exit with
};

MapRun audit_one(const AuditCommandOptions& options, const BatchMap& m, std::size_t index, std::size_t count) {
  const std::string which = "map " + std::to_string(index + 1) + " of " + std::to_string(count) + ": " + m.map;
  job::AuditRequest one = options.request;
  one.inputs.map = m.map;
  one.inputs.sensors = m.sensors;
  one.outputs.folder = map_folder(options, m);
  if (!options.quiet)
    std::cerr << "covmap audit: " << which << (m.sensors.empty() ? "" : " with " + m.sensors) << " -> "
              << one.outputs.folder.string() << "\n";
  try {
    if (!m.problem.empty()) throw io::InputError(m.map, 0, "", m.problem);
    const job::AuditedMap audited = job::run_audit_job(one, stderr_hooks(options.quiet));
    print_audit_summary(std::cout, one, audited);
    return {audited_outcome(m, audited), is_finding(options, audited) ? kFindings : kOk};
  } catch (const std::exception&) {
    const Failure failure = current_failure();
    std::cerr << "covmap audit: " << which << " failed: " << failure.message << "\n";
    return {failed_outcome(m, failure.message), failure.code};
  }
}

}  // namespace

int run_audit_batch(const AuditCommandOptions& options, const MapList& list) {
  for (const SkippedFile& s : list.skipped)
    std::cerr << "covmap audit: skipped " << s.file << ": " << skip_reason_words(s.reason) << "\n";
  check_outputs(options, list);
  mark_output_folder(options);
  BatchSummary summary{options.request.command_line, {}, list.skipped};
  int exit_code = kOk;  // the worst: internal error, bad input, findings, none (4 > 2 > 1 > 0)
  std::size_t failed = 0;
  for (std::size_t k = 0; k < list.maps.size(); ++k) {
    MapRun run = audit_one(options, list.maps[k], k, list.maps.size());
    exit_code = std::max(exit_code, run.exit_code);
    failed += run.outcome.status == MapStatus::kFailed;
    summary.maps.push_back(std::move(run.outcome));
  }
  const fs::path folder = io::normalized_output_path(options.request.outputs.folder.string());
  io::write_report_folder(folder, {{std::string(kSummaryCsv), summary_csv(summary)}, {std::string(kSummaryJson), summary_json(summary)}},
                          options.request.settings.force);
  std::cout << list.maps.size() << " maps: " << list.maps.size() - failed << " audited, " << failed << " failed -> "
            << (folder / kSummaryCsv).string() << ", " << kSummaryJson << "\n";
  return exit_code;
}

}  // namespace covmap::cli
