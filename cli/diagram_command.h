// covmap diagram SITES -o DIAGRAM.json [--svg DIAGRAM.svg]: the MWVD of a site file.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace covmap::cli {

struct DiagramOptions {
  std::string sites_path;
  std::string output_path;
  std::string svg_path;  // empty: no picture
  bool quiet = false;
};

void setup_diagram(CLI::App& app, DiagramOptions& options);
int run_diagram(const DiagramOptions& options);

}  // namespace covmap::cli
