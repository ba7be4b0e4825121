// What `covmap audit` says about one audited map: progress and notes on stderr while the job runs
// (job/audit_job.h), then the summary on stdout.
#pragma once

#include <iosfwd>

#include "cli/audit_command.h"
#include "job/audit_job.h"

namespace covmap::cli {

// The summary `covmap audit` prints on stdout for one audited map: a line that accounts for every
// sensor, the model fit and reception limit, then every sensor worth a look, by name.
void print_audit_summary(std::ostream& out, const job::AuditRequest& request, const job::AuditedMap& audited);

// Whether --fail-on-inconsistent makes this audit a finding (exit 1).
bool is_finding(const AuditCommandOptions& options, const job::AuditedMap& audited);

// The job's hooks on stderr: progress as "covmap audit: WHAT (SECONDS since this call)", nothing
// when quiet; notes as "covmap audit: note: ..." and forced plausibility findings as
// "covmap audit: warning: FILE: ...", always.
job::AuditJobHooks stderr_hooks(bool quiet);

}  // namespace covmap::cli
