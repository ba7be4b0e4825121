#include "cli/recognize_command.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "cli/cli_support.h"
#include "io/atomic_file.h"
#include "io/diagram_json.h"
#include "io/output_plan.h"
#include "report/reconstruction_json.h"
#include "report/svg.h"
#include "recognition/compare.h"
#include "recognition/graph_repair.h"
#include "recognition/recognize.h"
#include "voronoi/engine.h"

namespace covmap::cli {

CLI::App* setup_recognize(CLI::App& app, RecognizeOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "recognize", "Decide whether an arc graph is a weighted bisector graph / an MWVD and "
                   "reconstruct its sites (exit 0 yes, 3 no; 1 when the graph's own sites disagree "
                   "with the reconstruction)");
  cmd->add_option("graph", options.graph_path,
                  "a covmap.arcgraph/1 file (its sites, if any, are not used, only compared with the reconstruction)")
      ->required()
      ->check(input_file());
  cmd->add_option("-o,--output", options.output_path, "write covmap.reconstruction/1 JSON");
  cmd->add_option("--svg", options.svg_path,
                  "draw the recomputed diagram of the reconstruction (sites named and coloured as in the "
                  "graph's own sites when it has them)");
  cmd->add_option("--svg-width", options.svg_width,
                  "width of the SVG picture in pixels (default: from the sites' spacing, 800 to 4000)")
      ->check(positive_number());
  cmd->add_flag("--no-voronoi-check", options.no_voronoi_check,
                "skip recomputing the MWVD of the reconstruction");
  cmd->add_option("--tolerance", options.tolerance, "relative tolerance (times the graph's extent)")
      ->check(fraction())
      ->capture_default_str();
  return cmd;
}

namespace {

// "worst residual: arc 12 at (x, y): 3e-09 (allowed 1e-07)", or nothing when nothing was measured.
std::string worst_residual(const recognition::Reconstruction& r) {
  if (r.residuals.worst.empty()) return "";
  const recognition::Residual& w = r.residuals.worst.front();
  std::ostringstream out;
  out << "; worst residual: " << recognition::to_string(w.element) << " " << w.index << " at (" << w.x << ", " << w.y
      << "): " << w.amount << " (allowed " << w.allowed << ")";
  return out.str();
}

}  // namespace

int run_recognize(const RecognizeOptions& options) {
  return guarded([&]() {
    io::OutputPlan plan;
    plan.inputs = {options.graph_path};
    if (!options.output_path.empty()) plan.files.push_back(options.output_path);
    if (!options.svg_path.empty()) plan.files.push_back(options.svg_path);
    io::check_output_plan(plan);
    Diagram graph = io::read_diagram_json(options.graph_path, io::ArcLabels::kOptional);
    const std::vector<Site> input_sites = options.svg_path.empty() ? std::vector<Site>{} : graph.sites;
    const auto repairs = recognition::prepare_input_graph(graph);
    for (const auto& r : repairs) std::cerr << "covmap: repaired: " << r.what << "\n";
    recognition::RecognitionOptions ro;
    ro.voronoi_check = !options.no_voronoi_check;
    ro.relative_tolerance = options.tolerance;
    const recognition::Reconstruction r = recognition::recognize(std::move(graph), ro);
    // Render everything first; then all outputs are replaced together or none is.
    std::vector<io::FileText> outputs;
    if (!options.output_path.empty()) {
      std::ostringstream json;
      report::write_reconstruction_json(r, json);
      outputs.push_back({io::normalized_output_path(options.output_path), json.str()});
    }
    if (!options.svg_path.empty() && r.bisector_graph) {
      std::ostringstream svg;
      report::SvgOptions so;
      if (options.svg_width > 0) so.width_px = options.svg_width;
      // The input's ids where its labels pair them with the reconstruction: the same site then has
      // the same label and colour as in the picture of the diagram the graph came from.
      const std::vector<Site> sites =
          r.input_sites ? recognition::named_as_input(r.sites, input_sites, *r.input_sites) : r.sites;
      report::write_svg(voronoi::build_diagram(sites), svg, so);
      outputs.push_back({io::normalized_output_path(options.svg_path), svg.str()});
    }
    io::write_files_atomically(outputs);
    if (!r.bisector_graph) {
      std::cout << options.graph_path << ": not a bisector graph: " << r.reason << worst_residual(r) << "\n";
      return kNotBisectorGraph;
    }
    std::cout << options.graph_path << ": bisector graph of " << r.sites.size() << " sites"
              << (r.candidates.size() > 1 ? " (two solutions)" : "");
    if (r.region)
      std::cout << " (not unique: the site of face " << r.region->face << " may lie anywhere in a region of "
                << r.region->bounds.size() << " bounds; one choice given)";
    else if (!r.unique)
      std::cout << " (not unique: a one-parameter family; one member given)";
    std::cout << "; MWVD: " << recognition::to_string(r.voronoi);
    if (r.voronoi == recognition::MwvdAnswer::kNo && !r.voronoi_differences.empty())
      std::cout << " (" << r.voronoi_differences.size() << " differences; first: "
                << r.voronoi_differences.front().message << ")";
    std::cout << worst_residual(r) << "\n";
    if (r.input_sites) {
      const auto& in = *r.input_sites;
      std::cout << options.graph_path << ": the graph's own sites " << (in.agree ? "agree" : "disagree")
                << " with the reconstruction" << (in.positions_compared ? "" : " (labels only: the sites are not unique)");
      if (!in.agree)
        std::cout << " (" << in.differences.size() << " differences; first: " << in.differences.front().message << ")";
      std::cout << "\n";
      if (!in.agree) return kFindings;
    }
    return kOk;
  });
}

CLI::App* setup_compare(CLI::App& app, CompareCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand("compare", "Where two arc graphs differ (exit 0 equal, 1 not)");
  cmd->add_option("a", options.a_path, "first covmap.arcgraph/1 file")->required()->check(input_file());
  cmd->add_option("b", options.b_path, "second covmap.arcgraph/1 file")->required()->check(input_file());
  cmd->add_option("--tolerance", options.tolerance, "relative tolerance (times the graphs' extent)")
      ->check(fraction())
      ->capture_default_str();
  cmd->add_option("--show", options.show, "differences to list")
      ->check(whole_number_in(0, 1000000))
      ->capture_default_str();
  return cmd;
}

int run_compare(const CompareCommandOptions& options) {
  return guarded([&]() {
    const Diagram a = io::read_diagram_json(options.a_path, io::ArcLabels::kIgnored);
    const Diagram b = io::read_diagram_json(options.b_path, io::ArcLabels::kIgnored);
    recognition::CompareOptions co;
    co.relative_tolerance = options.tolerance;
    const recognition::Comparison c = recognition::compare_graphs(a, b, co);
    std::cout << c.brief() << "\n";
    int shown = 0;
    for (const auto& d : c.differences) {
      if (shown++ >= options.show) break;
      std::cout << "  " << recognition::to_string(d.kind) << " at (" << d.x << ", " << d.y
                << "): " << d.message << "\n";
    }
    return c.equal() ? kOk : kFindings;
  });
}

}  // namespace covmap::cli
