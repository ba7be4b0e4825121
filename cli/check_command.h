// covmap check DIAGRAM.json [--sites SITES]: verify any arc graph against the MWVD definition with
// the independent checker (check/), never the engine.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace covmap::cli {

// Limits of the option values: the check's cost grows with probes × sites and samples × arcs, so
// without a bound one mistyped number would run for hours.
inline constexpr long long kMaxProbes = 10'000'000;
inline constexpr long long kMaxSamplesPerArc = 10'000;

struct CheckCommandOptions {
  std::string diagram_path;
  std::string sites_path;  // empty: use the diagram's own sites
  int probes = 4000;
  int samples = 16;
  double tolerance = 1e-7;
  std::uint64_t seed = 1;
  int show = 20;  // violations listed on stdout
};

CLI::App* setup_check(CLI::App& app, CheckCommandOptions& options);
int run_check(const CheckCommandOptions& options);

}  // namespace covmap::cli
