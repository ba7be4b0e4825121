// covmap: reconstruct and verify sensor coverage maps. This file only wires the subcommands.
#include <CLI/CLI.hpp>

#include <string>

#include "cli/audit_command.h"
#include "cli/check_command.h"
#include "cli/diagram_command.h"
#include "cli/recognize_command.h"

int main(int argc, char** argv) {
  CLI::App app{"covmap: multiplicatively weighted Voronoi diagrams of sensor coverage maps"};
  app.require_subcommand(1);
  covmap::cli::DiagramOptions diagram;
  covmap::cli::CheckCommandOptions check;
  covmap::cli::setup_diagram(app, diagram);
  covmap::cli::setup_check(app, check);
  covmap::cli::RecognizeOptions recognize;
  covmap::cli::CompareCommandOptions compare;
  covmap::cli::setup_recognize(app, recognize);
  covmap::cli::setup_compare(app, compare);
  covmap::cli::AuditCommandOptions audit;
  for (int k = 0; k < argc; ++k) audit.command_line += (k ? " " : "") + std::string(argv[k]);
  covmap::cli::setup_audit(app, audit);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
