// covmap-make-map: realistic coverage maps from known sensors. This file only wires the command.
#include <CLI/CLI.hpp>

#include "tools/mapgen/make_map_command.h"

int main(int argc, char** argv) {
  CLI::App app{"covmap-make-map: a best-server coverage map (GeoJSON) with reported sensors and the truth"};
  covmap::mapgen::MakeMapOptions options;
  covmap::mapgen::setup_make_map(app, options);
  CLI11_PARSE(app, argc, argv);
  return covmap::mapgen::run_make_map(options);
}
