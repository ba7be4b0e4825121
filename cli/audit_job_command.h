// covmap audit-job REQUEST OUTCOME: the service's job process. Runs the audit a request file
// (job/audit_request_json.h) describes, with progress on stderr in `covmap audit`'s words and the
// summary on stdout, and leaves how it ended in OUTCOME (job/audit_outcome.h), written atomically.
// Hidden from --help: people run `covmap audit`; the service starts this in a process of its own so
// that a crash or a runaway input ends the job, never the server.
// Exit 0 when OUTCOME was written (whether the audit was done or failed); 4 when it could not be.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace covmap::cli {

struct AuditJobCommandOptions {
  std::string request_file;
  std::string outcome_file;
};

CLI::App* setup_audit_job(CLI::App& app, AuditJobCommandOptions& options);
int run_audit_job_command(const AuditJobCommandOptions& options);

}  // namespace covmap::cli
