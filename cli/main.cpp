// covmap: reconstruct and verify sensor coverage maps. This file only wires the subcommands and
// maps the command line's errors onto the exit-code contract (cli/cli_support.h).
#include <CLI/CLI.hpp>

#include <string>

#include "cli/audit_command.h"
#include "cli/audit_job_command.h"
#include "cli/check_command.h"
#include "cli/cli_support.h"
#include "cli/diagram_command.h"
#include "cli/recognize_command.h"
#include "cli/serve_command.h"
#include "io/interrupt_cleanup.h"

int main(int argc, char** argv) {
  using namespace covmap::cli;
  covmap::io::install_interrupt_cleanup();
  CLI::App app{"covmap: multiplicatively weighted Voronoi diagrams of sensor coverage maps"};
  app.set_version_flag("--version", "covmap " COVMAP_VERSION);
  app.require_subcommand(1);
  DiagramOptions diagram;
  CheckCommandOptions check;
  RecognizeOptions recognize;
  CompareCommandOptions compare;
  AuditCommandOptions audit;
  AuditJobCommandOptions audit_job;
  covmap::service::ServeOptions serve;
  for (int k = 0; k < argc; ++k) audit.request.command_line += (k ? " " : "") + std::string(argv[k]);
  const CLI::App* audit_cmd = setup_audit(app, audit);
  const CLI::App* diagram_cmd = setup_diagram(app, diagram);
  const CLI::App* recognize_cmd = setup_recognize(app, recognize);
  const CLI::App* compare_cmd = setup_compare(app, compare);
  const CLI::App* check_cmd = setup_check(app, check);
  const CLI::App* serve_cmd = setup_serve(app, serve);
  const CLI::App* audit_job_cmd = setup_audit_job(app, audit_job);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(app, e, argc, argv);
  }
  if (audit_cmd->parsed()) return run_audit(audit);
  if (diagram_cmd->parsed()) return run_diagram(diagram);
  if (recognize_cmd->parsed()) return run_recognize(recognize);
  if (compare_cmd->parsed()) return run_compare(compare);
  if (check_cmd->parsed()) return run_check(check);
  if (serve_cmd->parsed()) return run_serve(serve);
  if (audit_job_cmd->parsed()) return run_audit_job_command(audit_job);
  return kInternal;  // require_subcommand(1) makes this unreachable
}
