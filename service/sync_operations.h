// covmap::service synchronous operations: the small, quick commands of the CLI as request →
// response, same semantics and formats (docs/FORMATS.md):
//   diagram    sites (covmap.sites/1 JSON or CSV)       → the arc graph (covmap.arcgraph/1)
//   check      an arc graph                             → {"ok", "brief", "violations": [...]}
//   recognize  an arc graph                             → the reconstruction (covmap.reconstruction/1)
//   compare    {"a": arc graph, "b": arc graph}         → {"equal", "brief", "differences": [...]}
// Bad input throws ApiError kBadInput naming the item ("sites[3] (site 'b')"); an input over
// kMaxSyncSites sites throws kTooLarge pointing to the job API. The handlers are plain functions
// of text, so the server and tests call the same code.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace covmap::service {

// Sites (or arcs' sites) beyond which a synchronous answer would keep a connection for too long.
inline constexpr std::size_t kMaxSyncSites = 20'000;

std::string diagram_operation(std::string_view sites_text);
std::string check_operation(std::string_view graph_text);
std::string recognize_operation(std::string_view graph_text);
std::string compare_operation(std::string_view pair_json);

}  // namespace covmap::service
