#include "cli/diagram_command.h"

#include <chrono>
#include <filesystem>
#include <iostream>

#include "cli/cli_support.h"
#include "core/readable_numbers.h"
#include "io/atomic_file.h"
#include "io/diagram_json.h"
#include "io/input_error.h"
#include "io/output_plan.h"
#include "io/polygon_io.h"
#include "io/sites_io.h"
#include "report/svg.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::cli {

CLI::App* setup_diagram(CLI::App& app, DiagramOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "diagram", "Compute the multiplicatively weighted Voronoi diagram of a site file");
  cmd->add_option("sites", options.sites_path, "sites as covmap.sites/1 JSON or CSV (id,x,y,weight, optionally name)")
      ->required()
      ->check(input_file());
  cmd->add_option("-o,--output", options.output_path, "write the diagram (covmap.arcgraph/1)")
      ->required();
  cmd->add_option("--svg", options.svg_path,
                  "also draw the diagram as SVG (labels: the sites' names, else ids, where they fit; a scale bar)");
  cmd->add_option("--svg-width", options.svg_width,
                  "width of the SVG picture in pixels (default: from the sites' spacing, 800 to 4000)")
      ->check(positive_number());
  cmd->add_option("--clip", options.clip,
                  "clip to a rectangle 'xmin,ymin,xmax,ymax' or a polygon file (covmap.polygon/1 "
                  "or GeoJSON Polygon)");
  cmd->add_flag("-q,--quiet", options.quiet, "print nothing on success");
  return cmd;
}

int run_diagram(const DiagramOptions& options) {
  return guarded([&]() {
    const auto start = std::chrono::steady_clock::now();
    io::OutputPlan plan;
    plan.inputs = {options.sites_path};
    if (!options.clip.empty() && std::filesystem::exists(options.clip)) plan.inputs.push_back(options.clip);
    plan.files = {options.output_path};
    if (!options.svg_path.empty()) plan.files.push_back(options.svg_path);
    io::check_output_plan(plan);
    const io::SiteTable table = io::read_sites(options.sites_path);
    voronoi::BuildStats stats;
    Diagram diagram;
    try {
      diagram = voronoi::build_diagram(table.sites, &stats);
    } catch (const voronoi::InvalidSites& e) {
      // Name the offending sites by where they were read from.
      std::vector<io::InputProblem> problems;
      for (const auto& p : e.problems())
        problems.push_back({0, table.origin.at(p.index) + " (site '" + p.id + "')", p.problem});
      throw io::InputError(options.sites_path, std::move(problems));
    }
    if (!options.clip.empty()) diagram = voronoi::clip_diagram(diagram, io::parse_clip(options.clip));
    // Each output is written straight into its temporary (a large arc graph is gigabytes of text:
    // never held in memory); then all are put in place together, or none.
    io::StagedFiles outputs;
    outputs.stage(io::normalized_output_path(options.output_path),
                  [&diagram](std::ostream& out) { io::write_diagram_json(diagram, out); });
    if (!options.svg_path.empty()) {
      report::SvgOptions so;
      if (options.svg_width > 0) so.width_px = options.svg_width;
      outputs.stage(io::normalized_output_path(options.svg_path),
                    [&](std::ostream& out) { report::write_svg(diagram, out, so); });
    }
    outputs.commit();
    if (!options.quiet) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cout << "covmap diagram: " << plural(diagram.sites.size(), "site") << ", "
                << plural(diagram.nodes.size(), "node") << ", " << plural(diagram.arcs.size(), "arc") << ", "
                << plural(diagram.faces.size(), "face") << " in " << seconds(elapsed) << " -> "
                << options.output_path << (options.svg_path.empty() ? "" : ", " + options.svg_path) << "\n";
    }
    return kOk;
  });
}

}  // namespace covmap::cli
