// One map's audit, from its files to its report folder: what `covmap audit MAP -o OUTDIR/` does,
// and what `covmap audit` on several maps (cli/audit_batch.h) does for each of them. A service can
// call audit_map with its own options and folder.
//
// Contract
//  - Accepted: options.map_path (any map gis/map_reader.h reads), options.sensors_path (empty: no
//    reported sensors), options.output_dir and every other option of AuditCommandOptions.
//  - Guaranteed: the output plan (io/output_plan.h) is checked before anything is read; the report
//    folder is written all or nothing; options.inputs is not looked at.
//  - Rejected: bad input, implausible input without options.force, and outputs that may not be
//    written throw the typed errors cli/cli_support.h turns into exit 2 (current_failure() says
//    which); anything else is a bug.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

#include "audit/audit.h"
#include "cli/audit_command.h"
#include "report/audit_report.h"

namespace covmap::cli {

// Hears what the audit is doing, one short sentence at a time ("reading the map (0.2 MB)").
using AuditProgress = std::function<void(const std::string& what)>;

struct AuditedMap {
  audit::AuditResult result;
  report::AuditVerdictCounts counts;
};

AuditedMap audit_map(const AuditCommandOptions& options, const AuditProgress& progress = {});

// The summary `covmap audit` prints on stdout for one audited map: a line that accounts for every
// sensor, the model fit and reception limit, then every sensor worth a look, by name.
void print_audit_summary(std::ostream& out, const AuditCommandOptions& options, const AuditedMap& audited);

// Whether --fail-on-inconsistent makes this audit a finding (exit 1).
bool is_finding(const AuditCommandOptions& options, const AuditedMap& audited);

// Progress on stderr as "covmap audit: WHAT (SECONDS since this call)"; nothing when quiet.
AuditProgress stderr_progress(bool quiet);

}  // namespace covmap::cli
