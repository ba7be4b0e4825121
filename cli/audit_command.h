// covmap audit MAP [--sensors S] [--alpha 3.5] -o OUTDIR/: does a coverage map agree with the
// sensors that drew it? MAP is GeoJSON, any GDAL vector layer or a best-server raster, in lon/lat
// or a projected CRS (gis/map_reader.h). The audit itself is the job library's (job/audit_job.h):
// this command fills its request from the flags, runs it and prints the summary
// (cli/audit_summary.h). covmap audit MAP1 MAP2 ... | FOLDER -o OUTDIR/: a batch, each map's
// reports in OUTDIR/<map>/ and a summary table beside them (cli/audit_batch.h).
// Exit 0: audited (whatever the verdicts, unless --fail-on-inconsistent: then 1 when a reported
// sensor is inconsistent); 2: bad input or an output that may not be written (in a batch: any map
// failed); 4: internal error.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "job/audit_request.h"

namespace covmap::cli {

struct AuditCommandOptions {
  std::vector<std::string> inputs;   // the MAP and FOLDER arguments as typed (cli/audit_batch_inputs.h)
  // The audit's request: the map (set by run_audit from inputs, per map in a batch), the sensors,
  // the output folder and every option; command_line is recorded in the reports.
  job::AuditRequest request;
  bool quiet = false;                // no progress on stderr
  bool fail_on_inconsistent = false; // exit 1 when a reported sensor is inconsistent
};

CLI::App* setup_audit(CLI::App& app, AuditCommandOptions& options);
int run_audit(const AuditCommandOptions& options);

}  // namespace covmap::cli
