#include "report/reconstruction_json.h"

#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>
#include <ostream>

namespace covmap::report {
namespace {

nlohmann::json sites_json(const std::vector<Site>& sites) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& s : sites) a.push_back({{"id", s.id}, {"x", s.x}, {"y", s.y}, {"weight", s.weight}});
  return a;
}

nlohmann::json index_or_null(int i) { return i == kNone ? nlohmann::json() : nlohmann::json(i); }

// A bound of a site region: the open disk, the outside of a circle, or a half-plane.
nlohmann::json bound_json(const mobius::GeneralizedCircle& g) {
  if (g.is_line()) {
    // 2Re(B̄z) + C < 0: the side the normal -B points to; the line's direction keeps it on the left.
    const mobius::Complex n = g.B / std::abs(g.B);
    const mobius::Complex p = -g.C * g.B / (2.0 * std::norm(g.B));
    const mobius::Complex d = n * mobius::Complex(0.0, 1.0);
    return {{"line", {{"x", p.real()}, {"y", p.imag()}, {"dx", d.real()}, {"dy", d.imag()}}}, {"side", "left"}};
  }
  const mobius::Complex c = -g.B / g.A;
  const double r = std::sqrt(std::max(0.0, std::norm(c) - g.C / g.A));
  return {{"circle", {{"cx", c.real()}, {"cy", c.imag()}, {"r", r}}}, {"side", g.A > 0 ? "inside" : "outside"}};
}

}  // namespace

void write_reconstruction_json(const recognition::Reconstruction& r, std::ostream& out) {
  nlohmann::json j;
  j["format"] = "covmap.reconstruction/1";
  j["bisector_graph"] = r.bisector_graph;
  j["voronoi"] = std::string(recognition::to_string(r.voronoi));
  j["supported"] = true;  // covmap.reconstruction/1 keeps the member; every graph is handled now
  j["reason"] = r.reason;
  j["sites"] = sites_json(r.sites);
  j["unique"] = r.unique;
  if (r.region) {
    nlohmann::json bounds = nlohmann::json::array();
    for (const auto& b : r.region->bounds) bounds.push_back(bound_json(b));
    j["region"] = {{"face", r.region->face},
                   {"representative", {{"x", r.region->representative.x}, {"y", r.region->representative.y}}},
                   {"margin", r.region->margin},
                   {"bounds", bounds}};
  } else {
    j["region"] = nullptr;
  }
  j["candidates"] = nlohmann::json::array();
  for (const auto& c : r.candidates) j["candidates"].push_back(sites_json(c));
  j["faces"] = nlohmann::json::array();
  for (std::size_t f = 0; f < r.face_site.size(); ++f) {
    const auto& face = r.graph.faces[f];
    nlohmann::json boundary = nlohmann::json::array();
    for (const auto cycle : face_cycles(r.graph, face)) {
      nlohmann::json c = nlohmann::json::array();
      for (const auto& h : cycle) c.push_back({h.arc, h.forward});
      boundary.push_back(c);
    }
    j["faces"].push_back({{"site", index_or_null(r.face_site[f])},
                          {"bounded", face.bounded},
                          {"boundaries", boundary}});
  }
  if (r.failure) {
    j["failure"] = {{"message", r.failure->message}, {"arc", index_or_null(r.failure->arc)},
                    {"node", index_or_null(r.failure->node)}, {"face", index_or_null(r.failure->face)},
                    {"x", r.failure->x}, {"y", r.failure->y}, {"amount", r.failure->amount},
                    {"arcs_beyond", r.failure->arcs_beyond}, {"nodes_beyond", r.failure->nodes_beyond}};
  } else {
    j["failure"] = nullptr;
  }
  nlohmann::json worst = nlohmann::json::array();
  for (const auto& x : r.residuals.worst)
    worst.push_back({{"element", std::string(recognition::to_string(x.element))}, {"index", x.index},
                     {"x", x.x}, {"y", x.y}, {"amount", x.amount}, {"allowed", x.allowed}});
  j["residuals"] = {{"tolerance", r.residuals.tolerance}, {"arcs_beyond", r.residuals.arcs_beyond},
                    {"nodes_beyond", r.residuals.nodes_beyond}, {"arcs_unverified", r.residuals.arcs_unverified},
                    {"worst", worst}};
  j["voronoi_differences"] = nlohmann::json::array();
  for (const auto& d : r.voronoi_differences)
    j["voronoi_differences"].push_back({{"kind", recognition::to_string(d.kind)},
                                        {"index", index_or_null(d.index)},
                                        {"x", d.x},
                                        {"y", d.y},
                                        {"message", d.message}});
  j["input_sites"] = nullptr;
  if (r.input_sites) {
    nlohmann::json differences = nlohmann::json::array();
    for (const auto& d : r.input_sites->differences)
      differences.push_back({{"kind", std::string(recognition::to_string(d.kind))},
                             {"site", index_or_null(d.input_site)},
                             {"reconstructed_site", index_or_null(d.reconstructed_site)},
                             {"arc", index_or_null(d.arc)},
                             {"amount", d.amount},
                             {"relative", std::isfinite(d.relative) ? nlohmann::json(d.relative) : nlohmann::json()},
                             {"message", d.message}});
    j["input_sites"] = {{"agree", r.input_sites->agree},
                        {"positions_compared", r.input_sites->positions_compared},
                        {"differences", differences}};
  }
  out << j.dump() << "\n";
}

}  // namespace covmap::report
