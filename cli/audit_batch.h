// `covmap audit MAP1 MAP2 ... -o OUTDIR/` and `covmap audit FOLDER -o OUTDIR/`: several maps, each
// audited by the job library (job/audit_job.h) with the same options into OUTDIR/<folder>/, then
// OUTDIR/summary.csv and OUTDIR/summary.json (cli/audit_batch_summary.h). Which maps, their
// sensors and folders: cli/audit_batch_inputs.h.
//
// Contract
//  - Before any map is read, every output is checked (io/output_plan.h): OUTDIR as a report folder
//    holding the summaries and the maps' folders, and each map's folder as a report folder; no
//    output may be an input (a map, a sensors file or a folder argument). A refusal stops the
//    batch with exit 2 and writes nothing.
//  - OUTDIR is covmap's: its marker lists the two summaries, and each map's folder carries its own
//    marker listing its reports. A new or empty OUTDIR gets its marker before the first map is
//    audited, so a batch that is killed leaves a folder the next run may write into. Folders of
//    maps an earlier batch audited and this one does not are left as they are.
//  - Each map's folder is written all or nothing when its audit ends; a map that fails (bad input,
//    implausible input without --force, or a bug) is said on stderr and in the summaries, and the
//    next map is audited. The summaries are written last, together.
//  - Exit: 4 if a map met an internal error, else 2 if a map failed, else 1 with
//    --fail-on-inconsistent when a map has an inconsistent sensor, else 0.
#pragma once

#include "cli/audit_batch_inputs.h"
#include "cli/audit_command.h"

namespace covmap::cli {

// options.inputs and options.request.inputs.map are not looked at: `maps` are audited.
int run_audit_batch(const AuditCommandOptions& options, const MapList& maps);

}  // namespace covmap::cli
