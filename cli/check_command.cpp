#include "cli/check_command.h"

#include <algorithm>
#include <iomanip>
#include <iostream>

#include "cli/cli_support.h"
#include "io/diagram_json.h"
#include "io/input_error.h"
#include "io/sites_io.h"
#include "check/check.h"

namespace covmap::cli {

CLI::App* setup_check(CLI::App& app, CheckCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "check", "Verify an arc graph (ours or another tool's) against the MWVD of its sites");
  cmd->add_option("diagram", options.diagram_path, "a covmap.arcgraph/1 file")
      ->required()
      ->check(input_file());
  cmd->add_option("--sites", options.sites_path,
                  "check against these sites instead of the diagram's own (JSON or CSV)")
      ->check(input_file());
  cmd->add_option("--probes", options.probes, "boundary probes for the coverage test")
      ->check(whole_number_in(0, kMaxProbes))
      ->capture_default_str();
  cmd->add_option("--samples", options.samples, "sample points per arc")
      ->check(whole_number_in(1, kMaxSamplesPerArc))
      ->capture_default_str();
  cmd->add_option("--tolerance", options.tolerance,
                  "relative tolerance (times the diagonal of the sites' bounding box)")
      ->check(fraction())
      ->capture_default_str();
  cmd->add_option("--seed", options.seed, "probe seed")->capture_default_str();
  cmd->add_option("--show", options.show, "violations to list")
      ->check(whole_number_in(0, 1000000))
      ->capture_default_str();
  return cmd;
}

int run_check(const CheckCommandOptions& options) {
  return guarded([&]() {
    Diagram diagram = io::read_diagram_json(options.diagram_path);
    if (!options.sites_path.empty()) {
      io::SiteTable table = io::read_sites(options.sites_path);
      if (table.sites.size() != diagram.sites.size() && !diagram.sites.empty())
        throw io::InputError(options.sites_path, 0, "",
                             std::to_string(table.sites.size()) + " sites, but the diagram '" + options.diagram_path +
                                 "' has " + std::to_string(diagram.sites.size()));
      diagram.sites = std::move(table.sites);
    }
    check::CheckOptions check;
    check.boundary_probes = options.probes;
    check.samples_per_arc = options.samples;
    check.relative_tolerance = options.tolerance;
    // The probes' bisection must stay well below the tolerance the user chose.
    check.bisection_tolerance = std::min(check.bisection_tolerance, options.tolerance * 1e-3);
    check.seed = options.seed;
    check.max_reported = std::max(options.show, 1);
    std::string why;
    if (!check.is_valid(&why)) throw std::invalid_argument(why);
    const check::CheckReport report = check::check_diagram(diagram, check);
    std::cout << options.diagram_path << ": " << report.brief() << "\n";
    int listed = 0;
    std::cout << std::setprecision(17);
    for (const auto& v : report.violations) {
      if (listed++ >= options.show) break;
      std::cout << "  " << check::to_string(v.kind) << " at (" << v.x << ", " << v.y
                << "): " << v.message << "\n";
    }
    return report.ok() ? kOk : kFindings;
  });
}

}  // namespace covmap::cli
