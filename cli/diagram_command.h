// covmap diagram SITES -o DIAGRAM.json [--svg DIAGRAM.svg [--svg-width PX]] [--clip RECT|POLYGON]:
// the MWVD of a site file, optionally clipped to a rectangle or simple polygon.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace covmap::cli {

struct DiagramOptions {
  std::string sites_path;
  std::string output_path;
  std::string svg_path;  // empty: no picture
  double svg_width = 0;  // the picture's width in pixels; 0 (not given): chosen from the data
  std::string clip;      // empty: unclipped; "xmin,ymin,xmax,ymax" or a polygon file
  bool quiet = false;
};

CLI::App* setup_diagram(CLI::App& app, DiagramOptions& options);
int run_diagram(const DiagramOptions& options);

}  // namespace covmap::cli
