// A binary cache of engine diagrams for the benchmarks: building the MWVD of 10^6 sites takes
// longer than recognizing it, so the recognition benchmark can keep the graph between runs. Only
// nodes and arcs are stored (recognition reads nothing else); the file is raw memory of this build
// and is not an exchange format.
#pragma once

#include <optional>
#include <string>

#include "core/diagram.h"

namespace covmap::bench {

// Nodes and arcs of `d` written to `path` (atomically, through a temporary file).
void save_graph(const Diagram& d, const std::string& path);

// The graph stored at `path`, or nullopt when there is none or it is from another build.
std::optional<Diagram> load_graph(const std::string& path);

}  // namespace covmap::bench
