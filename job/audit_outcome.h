// covmap::job outcomes: how one audit job ended, as plain data and as the small JSON file a job's
// process leaves for the service (covmap.audit-outcome/1), so that the service learns the outcome
// from a typed record rather than from the process's messages.
//
//   {"format": "covmap.audit-outcome/1", "status": "done", "summary": {...report.json's summary...}}
//   {"format": "covmap.audit-outcome/1", "status": "failed",
//    "failure": {"kind": "bad_input", "message": "...", "input": "sensors", "item": "..."}}
//
// Contract: outcome_from_json(outcome_json(o)) == o for every outcome; outcome_from_json refuses
// any other text with std::invalid_argument (a process that died before writing leaves none).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "job/audit_job.h"

namespace covmap::job {

struct AuditOutcome {
  bool done = false;
  std::string summary_json;            // done: report.json's "summary" object, as JSON text
  std::optional<AuditFailure> failure; // failed: why

  friend bool operator==(const AuditOutcome& a, const AuditOutcome& b);
};

// "bad_input", "internal"; "map", "sensors", "raster_table", "" (kNone).
std::string_view failure_kind_name(FailureKind kind);
std::string_view input_kind_name(AuditInputKind input);

// A finished audit's outcome; a failure's outcome from describe_current_failure().
AuditOutcome done_outcome(const AuditedMap& audited);
AuditOutcome failed_outcome(AuditFailure failure);

std::string outcome_json(const AuditOutcome& outcome);
AuditOutcome outcome_from_json(std::string_view text);

}  // namespace covmap::job
