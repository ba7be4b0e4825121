#include "io/reconstruction_json.h"

#include <nlohmann/json.hpp>
#include <ostream>

namespace covmap::io {
namespace {

nlohmann::json sites_json(const std::vector<voronoi::Site>& sites) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& s : sites) a.push_back({{"id", s.id}, {"x", s.x}, {"y", s.y}, {"weight", s.weight}});
  return a;
}

nlohmann::json index_or_null(int i) { return i == voronoi::kNone ? nlohmann::json() : nlohmann::json(i); }

}  // namespace

void write_reconstruction_json(const recognition::Reconstruction& r, std::ostream& out) {
  nlohmann::json j;
  j["format"] = "covmap.reconstruction/1";
  j["bisector_graph"] = r.bisector_graph;
  j["voronoi"] = r.voronoi;
  j["supported"] = r.supported;
  j["reason"] = r.reason;
  j["sites"] = sites_json(r.sites);
  j["candidates"] = nlohmann::json::array();
  for (const auto& c : r.candidates) j["candidates"].push_back(sites_json(c));
  j["faces"] = nlohmann::json::array();
  for (std::size_t f = 0; f < r.face_site.size(); ++f) {
    const auto& face = r.graph.faces[f];
    nlohmann::json boundary = nlohmann::json::array();
    for (const auto& cycle : face.boundaries) {
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
                    {"x", r.failure->x}, {"y", r.failure->y}, {"amount", r.failure->amount}};
  } else {
    j["failure"] = nullptr;
  }
  j["voronoi_differences"] = nlohmann::json::array();
  for (const auto& d : r.voronoi_differences)
    j["voronoi_differences"].push_back({{"kind", recognition::to_string(d.kind)},
                                        {"index", index_or_null(d.index)},
                                        {"x", d.x},
                                        {"y", d.y},
                                        {"message", d.message}});
  out << j.dump() << "\n";
}

}  // namespace covmap::io
