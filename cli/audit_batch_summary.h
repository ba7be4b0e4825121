// The summary table of a batch audit: OUTDIR/summary.csv and OUTDIR/summary.json, one row per map
// (docs/FORMATS.md, "Batch audits: summary.csv / summary.json", documents every column).
//
// Contract
//  - Both files have the same columns, in the same order, from one definition (summary_row):
//    summary.json's "maps" holds each row as an object (numbers as numbers, null where the CSV
//    field is empty), summary.csv each row as a line under a header of the column names.
//  - The counts by verdict are those of report.json's "summary" (same names), the agreements are
//    its agreement.*.mean_iou times 100, the model-fit numbers its "model_fit": every number in
//    the shortest form that reads back to the same double. A failed map has only its files, its
//    folder, its status and its error.
//  - summary.csv: comma-separated, lines ending in "\n", fields holding a comma, a quote or a line
//    break double-quoted with quotes doubled (RFC 4180's quoting); summary.json is valid JSON, bytes
//    that are not UTF-8 replaced by U+FFFD.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "audit/audit.h"
#include "cli/audit_batch_inputs.h"
#include "job/audit_job.h"
#include "report/audit_report.h"

namespace covmap::cli {

enum class MapStatus { kAudited, kFailed };
std::string_view to_string(MapStatus status);  // "audited", "failed"

// What became of one map of the batch.
struct MapOutcome {
  BatchMap input;
  MapStatus status = MapStatus::kFailed;
  report::AuditVerdictCounts counts;               // audited only
  double refined_agreement_percent = 0.0;          // audited only
  std::optional<double> reported_agreement_percent;
  audit::ModelFit model_fit;                       // known false: not measured (or failed)
  std::string error;                               // failed only: the message, as on stderr
};

MapOutcome audited_outcome(const BatchMap& input, const job::AuditedMap& audited);
MapOutcome failed_outcome(const BatchMap& input, const std::string& error);

struct BatchSummary {
  std::string command_line;
  std::vector<MapOutcome> maps;
  std::vector<SkippedFile> skipped;
};

std::string summary_csv(const BatchSummary& summary);
std::string summary_json(const BatchSummary& summary);

}  // namespace covmap::cli
