// covmap check DIAGRAM.json [--sites SITES]: verify any arc graph against the MWVD definition with
// the independent checker (check/), never the engine.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace covmap::cli {

struct CheckCommandOptions {
  std::string diagram_path;
  std::string sites_path;  // empty: use the diagram's own sites
  int probes = 4000;
  int samples = 16;
  double tolerance = 1e-7;
  std::uint64_t seed = 1;
  int show = 20;  // violations listed on stdout
};

void setup_check(CLI::App& app, CheckCommandOptions& options);
int run_check(const CheckCommandOptions& options);

}  // namespace covmap::cli
