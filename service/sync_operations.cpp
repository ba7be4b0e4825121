#include "service/sync_operations.h"

#include <nlohmann/json.hpp>

#include <sstream>

#include "check/check.h"
#include "io/diagram_json.h"
#include "io/input_error.h"
#include "io/sites_io.h"
#include "recognition/compare.h"
#include "recognition/graph_repair.h"
#include "recognition/recognize.h"
#include "report/reconstruction_json.h"
#include "service/api_error.h"
#include "voronoi/engine.h"

namespace covmap::service {
namespace {

using Json = nlohmann::json;

ApiError bad_input(const io::InputError& e, const std::string& part) {
  std::string where = part;
  if (!e.problems.empty() && !e.problems.front().item.empty()) where += ": " + e.problems.front().item;
  return ApiError(ErrorCode::kBadInput, e.what(), where);
}

void check_size(std::size_t sites, const std::string& part) {
  if (sites > kMaxSyncSites)
    throw ApiError(ErrorCode::kTooLarge,
                   std::to_string(sites) + " sites; synchronous operations take at most " + std::to_string(kMaxSyncSites) +
                       ": submit larger inputs as a job (POST /v1/audits) or use the command line",
                   part);
}

Diagram read_graph(std::string_view text, const std::string& part, io::ArcLabels labels) {
  try {
    Diagram d = io::parse_diagram_json(text, part, labels);
    check_size(d.sites.size(), part);
    return d;
  } catch (const io::InputError& e) {
    throw bad_input(e, part);
  }
}

Json point(double x, double y) { return Json::array({x, y}); }

}  // namespace

std::string diagram_operation(std::string_view sites_text) {
  io::SiteTable table;
  try {
    table = io::parse_sites(sites_text, "sites");
  } catch (const io::InputError& e) {
    throw bad_input(e, "sites");
  }
  check_size(table.sites.size(), "sites");
  Diagram diagram;
  try {
    diagram = voronoi::build_diagram(table.sites);
  } catch (const voronoi::InvalidSites& e) {
    std::vector<io::InputProblem> problems;
    for (const auto& p : e.problems()) problems.push_back({0, table.origin.at(p.index) + " (site '" + p.id + "')", p.problem});
    throw bad_input(io::InputError("sites", std::move(problems)), "sites");
  }
  std::ostringstream out;
  io::write_diagram_json(diagram, out);
  return out.str();
}

std::string check_operation(std::string_view graph_text) {
  const Diagram diagram = read_graph(graph_text, "diagram", io::ArcLabels::kRequired);
  const check::CheckReport report = check::check_diagram(diagram, check::CheckOptions{});
  Json violations = Json::array();
  for (const auto& v : report.violations)
    violations.push_back({{"kind", check::to_string(v.kind)}, {"at", point(v.x, v.y)}, {"message", v.message}});
  return Json{{"ok", report.ok()}, {"brief", report.brief()}, {"violations", violations}}.dump();
}

std::string recognize_operation(std::string_view graph_text) {
  Diagram graph = read_graph(graph_text, "graph", io::ArcLabels::kOptional);
  recognition::prepare_input_graph(graph);
  const recognition::Reconstruction r = recognition::recognize(std::move(graph), recognition::RecognitionOptions{});
  std::ostringstream out;
  report::write_reconstruction_json(r, out);
  return out.str();
}

std::string compare_operation(std::string_view pair_json) {
  const Json pair = Json::parse(pair_json, nullptr, false);
  if (pair.is_discarded() || !pair.is_object() || !pair.contains("a") || !pair.contains("b"))
    throw ApiError(ErrorCode::kBadInput, "expected a JSON object {\"a\": arc graph, \"b\": arc graph}", "body");
  const Diagram a = read_graph(pair["a"].dump(), "a", io::ArcLabels::kIgnored);
  const Diagram b = read_graph(pair["b"].dump(), "b", io::ArcLabels::kIgnored);
  const recognition::Comparison c = recognition::compare_graphs(a, b, recognition::CompareOptions{});
  Json differences = Json::array();
  for (const auto& d : c.differences)
    differences.push_back({{"kind", recognition::to_string(d.kind)}, {"at", point(d.x, d.y)}, {"message", d.message}});
  return Json{{"equal", c.equal()}, {"brief", c.brief()}, {"differences", differences}}.dump();
}

}  // namespace covmap::service
