#include "cli/diagram_command.h"

#include <chrono>
#include <iostream>
#include <sstream>

#include "cli/cli_support.h"
#include "io/atomic_file.h"
#include "io/diagram_json.h"
#include "io/polygon_io.h"
#include "io/sites_io.h"
#include "report/svg.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::cli {

void setup_diagram(CLI::App& app, DiagramOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "diagram", "Compute the multiplicatively weighted Voronoi diagram of a site file");
  cmd->add_option("sites", options.sites_path, "sites as covmap.sites/1 JSON or CSV (id,x,y,weight)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options.output_path, "write the diagram (covmap.arcgraph/1)")
      ->required();
  cmd->add_option("--svg", options.svg_path, "also draw the diagram as SVG");
  cmd->add_option("--clip", options.clip,
                  "clip to a rectangle 'xmin,ymin,xmax,ymax' or a polygon file (covmap.polygon/1 "
                  "or GeoJSON Polygon)");
  cmd->add_flag("-q,--quiet", options.quiet, "print nothing on success");
  cmd->callback([&options]() { std::exit(run_diagram(options)); });
}

int run_diagram(const DiagramOptions& options) {
  return guarded([&]() {
    const auto start = std::chrono::steady_clock::now();
    const io::SiteTable table = io::read_sites(options.sites_path);
    voronoi::BuildStats stats;
    Diagram diagram;
    try {
      diagram = voronoi::build_diagram(table.sites, &stats);
    } catch (const voronoi::InvalidSites& e) {
      // Name the offending sites by where they were read from.
      std::ostringstream msg;
      msg << options.sites_path << ": " << e.problems().size() << " invalid site(s)";
      for (const auto& p : e.problems())
        msg << "\n  " << table.origin.at(p.index) << " (site '" << p.id << "'): " << p.problem;
      throw std::invalid_argument(msg.str());
    }
    if (!options.clip.empty()) diagram = voronoi::clip_diagram(diagram, io::parse_clip(options.clip));
    // Render everything before writing anything, so a failure leaves no partial output.
    std::ostringstream json, svg;
    io::write_diagram_json(diagram, json);
    if (!options.svg_path.empty()) report::write_svg(diagram, svg);
    io::write_file_atomically(options.output_path, [&](std::ostream& out) { out << json.str(); });
    if (!options.svg_path.empty())
      io::write_file_atomically(options.svg_path, [&](std::ostream& out) { out << svg.str(); });
    if (!options.quiet) {
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cout << "covmap diagram: " << diagram.sites.size() << " sites, " << diagram.nodes.size()
                << " nodes, " << diagram.arcs.size() << " arcs, " << diagram.faces.size()
                << " faces in " << seconds << " s -> " << options.output_path
                << (options.svg_path.empty() ? "" : ", " + options.svg_path) << "\n";
    }
    return kOk;
  });
}

}  // namespace covmap::cli
