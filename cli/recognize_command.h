// covmap recognize GRAPH.json [-o RECONSTRUCTION.json] [--svg PIC.svg [--svg-width PX]] [--no-voronoi-check]:
// is the graph a weighted bisector graph / an MWVD, and which sites drew it?
// Exit 0: bisector graph; 3: not a bisector graph; 2: bad input (5, not handled yet, is reserved).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace covmap::cli {

struct RecognizeOptions {
  std::string graph_path;
  std::string output_path;
  std::string svg_path;
  double svg_width = 0;  // the picture's width in pixels; 0 (not given): chosen from the data
  bool no_voronoi_check = false;
  double tolerance = 1e-7;
};

CLI::App* setup_recognize(CLI::App& app, RecognizeOptions& options);
int run_recognize(const RecognizeOptions& options);

// covmap compare A.json B.json: where two arc graphs differ. Exit 0 equal, 1 different.
struct CompareCommandOptions {
  std::string a_path, b_path;
  double tolerance = 1e-7;
  int show = 20;
};

CLI::App* setup_compare(CLI::App& app, CompareCommandOptions& options);
int run_compare(const CompareCommandOptions& options);

}  // namespace covmap::cli
