// covmap-make-map: make a coverage map (map.geojson, sensors.geojson, truth.json) from known sensors.
//
//   covmap-make-map --sites datasets/swiss_towns.csv --bin 500 --lonlat 8.0084,47.1044 --jitter 2
//                   --gross-fraction 0.1 --seed 1 -o outdir/
//
//   covmap-make-map --towns datasets/towns/nordrhein_westfalen.csv --count 150 --model shadowing
//                   --max-range 8000 --seed 3 -o outdir/
//
// Input, exactly one of: --sites FILE (covmap sites CSV/JSON, coordinates in --unit km|m, default
// km as in datasets/swiss_towns.csv), --lonlat-sites FILE (CSV id,lon,lat,weight, e.g. from
// cities_sites.js --lonlat), --random N (uniform in --area W,H km, log-uniform weights within
// --weight-ratio), --towns FILE (a window of --count real towns from a lon/lat town list, chosen by
// --seed, weights from population or --town-weights power-classes; town_layouts.h). Output in
// lon/lat about --lonlat LON,LAT (lon/lat input: by default, about the centre of its bounding box;
// --planar keeps metres). --model picks the propagation model (propagation_model.h). The files are written atomically (temporary
// directory, then renames); a one-line summary goes to stdout.
// Exit status: 0 done; 2 bad input or options (the message names file, line and problem); 3 the
// output could not be written (nothing half-written is left); 4 an internal error.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "tools/mapgen/coverage_map_generator.h"

namespace covmap::mapgen {

struct MakeMapOptions {
  std::string sites_path;                              // --sites: planar covmap sites file
  std::string unit = "km";                             // --unit: km or m, for --sites
  std::string lonlat_sites_path;                       // --lonlat-sites: CSV id,lon,lat,weight
  int random_count = 0;                                // --random: number of random sensors (0: off)
  std::vector<double> random_area_km = {50.0, 50.0};   // --area: W,H of the random layout, km
  double random_weight_ratio = 4.0;                    // --weight-ratio: largest/smallest random weight
  std::string towns_path;                              // --towns: lon/lat town list (CSV id,lon,lat,weight)
  int town_count = 100;                                // --count: towns in the window
  std::string town_weights = "population";             // --town-weights: population | power-classes
  std::vector<double> power_classes_dbm = {43.0, 37.0, 31.0};  // --power-classes: dBm, for power-classes
  std::string model = "multiplicative";                // --model: propagation model name
  std::vector<double> lonlat_centre;                   // --lonlat: LON,LAT (empty: not given)
  bool planar = false;                                 // --planar: metres even for lon/lat input
  std::vector<double> extent;                          // --extent: xmin,ymin,xmax,ymax metres (empty: auto)
  std::vector<double> gross_position_m;                // --gross-position: MIN,MAX (empty: default)
  std::vector<double> gross_power_db;                  // --gross-power: MIN,MAX (empty: default)
  CoverageMapOptions map;                              // everything else, flag by flag
  std::string output_dir;                              // -o: directory for the three files
  bool quiet = false;                                  // -q: no summary
};

enum MakeMapExit : int { kMakeMapOk = 0, kMakeMapBadInput = 2, kMakeMapCannotWrite = 3, kMakeMapInternal = 4 };

// Declares the flags on `app` (the program has no subcommands).
void setup_make_map(CLI::App& app, MakeMapOptions& options);
// Does the work; returns an exit status, with any error message on stderr.
int run_make_map(const MakeMapOptions& options);

}  // namespace covmap::mapgen
