#include "cli/audit_job_command.h"

#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/audit_summary.h"
#include "cli/cli_support.h"
#include "io/atomic_file.h"
#include "job/audit_outcome.h"
#include "job/audit_request_json.h"

namespace covmap::cli {
namespace {

job::AuditRequest read_request(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw std::runtime_error("cannot read the job's request " + file);
  return job::request_from_json(text.str());
}

job::AuditOutcome run_job(const AuditJobCommandOptions& options) {
  job::AuditRequest request;
  try {
    request = read_request(options.request_file);
    const job::AuditedMap audited = job::run_audit_job(request, stderr_hooks(false));
    print_audit_summary(std::cout, request, audited);
    return job::done_outcome(audited);
  } catch (const std::exception&) {
    return job::failed_outcome(job::describe_current_failure(&request));
  }
}

}  // namespace

CLI::App* setup_audit_job(CLI::App& app, AuditJobCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand("audit-job", "Run one audit job from a request file (the service's worker process)");
  cmd->group("");  // hidden: an interface between the service and its processes, not for people
  cmd->add_option("request", options.request_file, "covmap.audit-request/1 JSON")->required()->check(input_file());
  cmd->add_option("outcome", options.outcome_file, "where covmap.audit-outcome/1 JSON is written")->required();
  return cmd;
}

int run_audit_job_command(const AuditJobCommandOptions& options) {
  return guarded([&]() -> int {
    const job::AuditOutcome outcome = run_job(options);
    io::write_files_atomically({{options.outcome_file, job::outcome_json(outcome)}});
    return kOk;
  });
}

}  // namespace covmap::cli
