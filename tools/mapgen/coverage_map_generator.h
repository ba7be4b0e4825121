// covmap::mapgen::generate_coverage_map — a coverage map as radio-planning tools export it, made
// from known ("true") sensors, with the sensor list an operator would report.
//
// What is made
//  1. The true sensors are placed in a plane (metres): planar input as given; lon/lat input through
//     io::LocalProjection (transverse Mercator about `centre`, see map_projection.h). Weights are scaled
//     so the largest is 1, and tx_power_dbm = 10 · alpha · log10(weight) + reference_power_dbm.
//  2. A best-server raster of square bins (voronoi/best_server_raster.h): each bin centre belongs to the
//     sensor minimizing distance / weight, ties to the lowest index; with max_range_m, bins whose
//     smallest distance / weight exceeds it are not covered. With another propagation model
//     (options.propagation, propagation_model.h) each bin centre belongs to the sensor of largest
//     received power instead (received_power_raster.h), and max_range_m becomes the sensitivity
//     P0 − 10·α·log10(max_range_m): the same limit for the multiplicative model.
//  3. The cells: each 4-connected component of a sensor's bins becomes a polygon with its holes
//     (raster_polygons.h), optionally without the vertices inside straight runs, then every vertex
//     jittered by N(0, vertex_jitter_m²) per coordinate, independently per sensor (neighbouring
//     sensors show small gaps and overlaps, as after a tool's re-projection; a corner shared by two
//     rings of one sensor moves as one), projected to lon/lat when asked, and rounded to
//     coordinate_digits decimals.
//  4. Reported sensors: the true ones with the errors of reported_sensors.h, rounded the same way
//     (powers to power_digits); their weights follow from the reported powers. The propagation
//     model changes only the raster: reports are as correct under every model.
// Same input, options and seed → identical result and identical files, on every platform.
//
// Accepted: at least one sensor (two without an explicit extent or bin size, which are derived
// from the spacing); finite coordinates (lon in [-180, 180], lat in (-90, 90)); finite positive
// weights; unique non-empty ids; distinct positions. Options must pass is_valid. Rejected input or
// options throw std::invalid_argument with every problem named (site id and what is wrong).
// Guaranteed: the polygons of one sensor cover exactly its bins (area = bins × bin², before jitter
// and rounding); polygons of different sensors do not overlap (without jitter); rings are closed,
// simple, outer counter-clockwise, holes clockwise. Not guaranteed once jitter or coarse rounding
// is applied: those are the defects a real export has.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "voronoi/best_server_raster.h"
#include "io/local_projection.h"
#include "tools/mapgen/lonlat_site.h"
#include "tools/mapgen/propagation_model.h"
#include "tools/mapgen/reported_sensors.h"
#include "tools/mapgen/town_layouts.h"
#include "core/diagram.h"

namespace covmap::mapgen {

using voronoi::BestServerRaster;
using voronoi::RasterGrid;
using voronoi::best_server_raster;

enum class OutputFrame {
  kPlanar,  // coordinates in metres in the generator's plane
  kLonLat,  // GeoJSON's own: [lon, lat] in degrees (WGS84)
};

struct Rectangle {
  double xmin = 0.0;
  double ymin = 0.0;
  double xmax = 0.0;
  double ymax = 0.0;
};

struct CoverageMapOptions {
  // --- raster ---
  // Side of a square bin, metres. Unset: 1/20 of the mean nearest-neighbour spacing of the sensors,
  // rounded down to 1, 2 or 5 × 10^k (a planner's choice: a cell is then ~20 bins across). In a
  // clustered layout the densest sensors can then be fewer than 10 bins from their nearest
  // neighbour (datasets/towns/README.md says how to choose the bin by local spacing).
  std::optional<double> bin_size_m;
  // The area rasterized, plane metres; its edges are moved outwards to multiples of the bin size
  // (as tools align bins to a grid). Unset: the sensors' bounding box grown on each side by
  // extent_margin_spacings × their mean nearest-neighbour spacing.
  std::optional<Rectangle> extent;
  double extent_margin_spacings = 1.0;
  // Reach of a sensor of weight 1 (the strongest), metres; a sensor of weight w reaches w × this.
  // Bins farther (in distance / weight) from their best server are not covered, which gives an
  // irregular outer frame and possibly holes. Unset: every bin is covered.
  std::optional<double> max_range_m;
  // Rasters with more bins are refused (std::invalid_argument) instead of exhausting memory;
  // a bin costs about 10 bytes while the map is made.
  std::size_t max_bins = 50'000'000;

  // --- output coordinates ---
  OutputFrame frame = OutputFrame::kPlanar;
  // Centre of the projection. Needed for lon/lat output of planar input (the plane is then read as
  // transverse Mercator coordinates about it); for lon/lat input, unset means the centre of the
  // sensors' lon/lat bounding box. With planar input and output it only adds lon/lat to truth.json.
  std::optional<io::LonLat> centre;
  // Decimals of written coordinates. Unset: 6 for lon/lat (≈ 0.1 m), 2 for metres (1 cm).
  std::optional<int> coordinate_digits;
  int power_digits = 1;              // decimals of reported transmit powers (dB)
  double vertex_jitter_m = 0.0;      // std. deviation of each vertex coordinate's noise, metres (per sensor)
  bool simplify_collinear = true;    // drop vertices inside straight runs of the staircase

  // --- radio model: tx_power_dbm = 10 · alpha · log10(weight) + reference_power_dbm ---
  double alpha = 3.5;                  // path-loss exponent
  double reference_power_dbm = 43.0;   // power of the strongest (weight 1) sensor: 20 W, a macro cell

  // --- propagation: the default is the multiplicative model (the MWVD) ---
  PropagationOptions propagation;

  // --- reported sensors ---
  ReportErrorOptions errors;

  // Where the sensors came from, written to truth.json ("layout") when set; no effect on the map.
  std::optional<TownLayoutRecord> town_layout;

  std::uint64_t seed = 1;  // all randomness (errors, jitter) derives from it

  // False, with the reason in *why (when given), for any out-of-range field.
  bool is_valid(std::string* why) const;
};

struct TrueSensor {
  std::string id;
  std::string name;     // lon/lat input's name (LonLatSite::name), else empty; written to every file
  Point position;       // plane, metres
  std::optional<io::LonLat> lonlat;  // when a projection centre is known
  double weight = 1.0;           // scaled: the strongest sensor has weight 1
  double tx_power_dbm = 0.0;
  std::size_t bins = 0;          // bins it serves
  std::size_t cells = 0;         // connected components of those bins
};

struct ReportedSensor {
  std::string id;
  Point position;  // plane, metres, before rounding: true position + error.total_offset()
  Point output;    // as written: [lon, lat] or metres, rounded to coordinate_digits
  double tx_power_dbm = 0.0;  // rounded to power_digits
  double weight = 1.0;        // 10^((tx_power_dbm - reference_power_dbm) / (10 · alpha))
  SensorError error;
};

using Ring = std::vector<Point>;  // closed: front() == back()

// One connected component of a sensor's bins. rings[0] is the outer ring, then the holes.
struct MapCell {
  std::size_t bins = 0;
  std::vector<Ring> planar;  // metres, after jitter, before projection and rounding
  std::vector<Ring> output;  // as written: lon/lat or metres, rounded
};

struct MapFeature {
  int sensor = kNone;  // index into CoverageMap::truth
  std::vector<MapCell> cells;   // in the order of each cell's first bin, scanning rows south to north
};

struct CoverageMapCounts {
  std::size_t sensors = 0;
  std::size_t bins = 0;
  std::size_t covered_bins = 0;
  std::size_t cells = 0;
  std::size_t holes = 0;
  std::size_t vertices = 0;              // over all rings, the closing repeat not counted
  std::size_t sensors_without_bins = 0;  // dominated sensors: no feature in the map
  std::size_t gross_errors = 0;
};

// Wall-clock seconds per stage (not written to any file: the files must not depend on the machine).
struct CoverageMapTimings {
  double raster_seconds = 0.0;    // best-server labels
  double polygons_seconds = 0.0;  // tracing, jitter, projection, rounding
  double total_seconds = 0.0;
};

struct CoverageMap {
  CoverageMapOptions options;  // as used: bin size, extent, digits and centre filled in
  std::optional<io::LocalProjection> projection;  // set when a centre is known
  BestServerRaster raster;                  // labels index into truth
  std::vector<TrueSensor> truth;            // input order
  std::vector<ReportedSensor> reported;     // same order as truth
  std::vector<MapFeature> features;         // sensors with at least one bin, in sensor order
  // The propagation model as applied: per-sensor parameters (sensors empty for the multiplicative
  // model, which is labelled by distance / weight) and the sensitivity used with max_range_m.
  Propagation propagation;
  std::optional<double> sensitivity_dbm;
  CoverageMapCounts counts;
  CoverageMapTimings timings;
};

// Planar input: positions in metres.
CoverageMap generate_coverage_map(std::span<const Site> sites, const CoverageMapOptions& options);
// Lon/lat input: projected about options.centre (default: the centre of the lon/lat bounding box;
// sensors straddling the antimeridian need an explicit centre).
CoverageMap generate_coverage_map(std::span<const LonLatSite> sites, const CoverageMapOptions& options);

// The bin size used when none is given: mean_spacing / 20 rounded down to 1, 2 or 5 × 10^k.
double default_bin_size(double mean_spacing);

}  // namespace covmap::mapgen
