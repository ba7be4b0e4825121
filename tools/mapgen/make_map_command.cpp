#include "tools/mapgen/make_map_command.h"

#include <chrono>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "tools/mapgen/coverage_map_files.h"
#include "tools/mapgen/lonlat_sites_csv.h"
#include "tools/mapgen/site_layouts.h"
#include "tools/mapgen/town_layouts.h"
#include "io/input_error.h"
#include "io/sites_io.h"

namespace covmap::mapgen {

void setup_make_map(CLI::App& app, MakeMapOptions& o) {
  CoverageMapOptions& m = o.map;
  ReportErrorOptions& e = m.errors;
  auto* input = app.add_option_group("input", "where the true sensors come from (exactly one)");
  input->add_option("--sites", o.sites_path, "covmap sites file (CSV id,x,y,weight or covmap.sites/1 JSON)")
      ->check(CLI::ExistingFile);
  input->add_option("--lonlat-sites", o.lonlat_sites_path, "CSV with columns id,lon,lat,weight (degrees)")
      ->check(CLI::ExistingFile);
  input->add_option("--random", o.random_count, "N sensors uniform in --area, log-uniform weights")
      ->check(CLI::PositiveNumber);
  input->add_option("--towns", o.towns_path, "lon/lat town list (id,lon,lat,weight): a window of --count towns")
      ->check(CLI::ExistingFile);
  input->require_option(1);
  app.add_option("--count", o.town_count, "towns in the --towns window")->check(CLI::Range(2, 1'000'000))
      ->capture_default_str();
  app.add_option("--town-weights", o.town_weights, "weights of --towns: from population or from power classes")
      ->check(CLI::IsMember({std::string(to_string(TownWeights::kPopulation)),
                             std::string(to_string(TownWeights::kPowerClasses))}))
      ->capture_default_str();
  app.add_option("--power-classes", o.power_classes_dbm,
                 "tx powers (dBm) of --town-weights power-classes, most isolated towns get the highest")
      ->delimiter(',')->capture_default_str();
  std::vector<std::string> models;
  for (const PropagationModel model : kAllPropagationModels) models.emplace_back(to_string(model));
  app.add_option("--model", o.model, "propagation model")->check(CLI::IsMember(models))->capture_default_str();
  PropagationOptions& p = m.propagation;
  app.add_option("--alpha-spread", p.alpha_spread, "exponents model: std. deviation of each sensor's exponent")
      ->capture_default_str();
  app.add_option("--excess-loss-max", p.excess_loss_max_db_per_km,
                 "excess-loss model: each sensor's extra loss is uniform in [0, this] dB/km")->capture_default_str();
  app.add_option("--shadowing-sigma", p.shadowing_sigma_db, "shadowing model: std. deviation of each field, dB")
      ->capture_default_str();
  app.add_option("--shadowing-correlation", p.shadowing_correlation_m,
                 "shadowing model: correlation length, metres (default: mean sensor spacing)");
  app.add_option("--unit", o.unit, "unit of --sites coordinates")->check(CLI::IsMember({"km", "m"}))->capture_default_str();
  app.add_option("--area", o.random_area_km, "W,H of the --random area, km")->delimiter(',')->expected(2)
      ->capture_default_str();
  app.add_option("--weight-ratio", o.random_weight_ratio, "largest / smallest --random weight")->capture_default_str();

  app.add_option("--lonlat", o.lonlat_centre, "write lon/lat; LON,LAT is the projection centre")
      ->delimiter(',')->expected(2);
  app.add_flag("--planar", o.planar, "write metres even for --lonlat-sites input");
  app.add_option("--bin", m.bin_size_m, "bin size, metres (default: mean sensor spacing / 20, rounded down)");
  app.add_option("--extent", o.extent, "xmin,ymin,xmax,ymax in plane metres (default: sensors + margin)")
      ->delimiter(',')->expected(4);
  app.add_option("--margin", m.extent_margin_spacings, "automatic extent margin, in mean sensor spacings")
      ->capture_default_str();
  app.add_option("--max-range", m.max_range_m, "reach of the strongest sensor, metres (default: unlimited)");
  app.add_option("--digits", m.coordinate_digits, "decimals of coordinates (default 6 for lon/lat, 2 for metres)");
  app.add_option("--power-digits", m.power_digits, "decimals of reported powers")->capture_default_str();
  app.add_option("--jitter", m.vertex_jitter_m, "std. deviation of per-vertex noise, metres")->capture_default_str();
  app.add_flag("!--no-simplify", m.simplify_collinear, "keep every bin corner on the cell boundaries");
  app.add_option("--alpha", m.alpha, "path-loss exponent")->capture_default_str();
  app.add_option("--p0", m.reference_power_dbm, "transmit power of the strongest sensor, dBm")->capture_default_str();
  app.add_option("--position-sigma", e.position_sigma_m, "reported position error, std. deviation per axis, metres")
      ->capture_default_str();
  app.add_option("--power-sigma", e.power_sigma_db, "reported power error, std. deviation, dB")->capture_default_str();
  app.add_option("--gross-fraction", e.gross_fraction, "share of sensors with a gross error")->capture_default_str();
  app.add_option("--gross-position", o.gross_position_m, "MIN,MAX distance of a gross position error, metres")
      ->delimiter(',')->expected(2);
  app.add_option("--gross-power", o.gross_power_db, "MIN,MAX size of a gross power error, dB")
      ->delimiter(',')->expected(2);
  app.add_option("--seed", m.seed, "random seed (same seed, same files)")->capture_default_str();
  app.add_option("-o,--output", o.output_dir, "directory for map.geojson, sensors.geojson, truth.json")->required();
  app.add_flag("-q,--quiet", o.quiet, "print nothing on success");
}

namespace {

CoverageMap make(const MakeMapOptions& o) {
  CoverageMapOptions m = o.map;
  if (!o.extent.empty()) m.extent = Rectangle{o.extent[0], o.extent[1], o.extent[2], o.extent[3]};
  if (!o.gross_position_m.empty()) {
    m.errors.gross_position_min_m = o.gross_position_m[0];
    m.errors.gross_position_max_m = o.gross_position_m[1];
  }
  if (!o.gross_power_db.empty()) {
    m.errors.gross_power_min_db = o.gross_power_db[0];
    m.errors.gross_power_max_db = o.gross_power_db[1];
  }
  if (!o.lonlat_centre.empty()) {
    m.centre = io::LonLat{o.lonlat_centre[0], o.lonlat_centre[1]};
    m.frame = OutputFrame::kLonLat;
  }
  const auto model = propagation_model_from_string(o.model);
  if (!model) throw std::invalid_argument("unknown propagation model '" + o.model + "'");
  m.propagation.model = *model;
  if (!o.lonlat_sites_path.empty()) {
    m.frame = o.planar ? OutputFrame::kPlanar : OutputFrame::kLonLat;
    const LonLatSiteTable table = read_lonlat_sites_csv(o.lonlat_sites_path);
    return generate_coverage_map(std::span<const LonLatSite>(table.sites), m);
  }
  if (!o.towns_path.empty()) {
    m.frame = o.planar ? OutputFrame::kPlanar : OutputFrame::kLonLat;
    const LonLatSiteTable table = read_lonlat_sites_csv(o.towns_path);
    TownLayoutOptions t;
    t.count = o.town_count;
    const auto weights = town_weights_from_string(o.town_weights);
    if (!weights) throw std::invalid_argument("unknown town weights '" + o.town_weights + "'");
    t.weights = *weights;
    t.power_classes_dbm = o.power_classes_dbm;
    t.alpha = m.alpha;
    t.seed = m.seed;
    const TownWindow window = clustered_town_sites(table.sites, t);
    m.town_layout = TownLayoutRecord{o.towns_path, table.sites.size(), table.sites[window.centre].id, t.weights,
                                     t.weights == TownWeights::kPowerClasses ? t.power_classes_dbm : std::vector<double>{}};
    return generate_coverage_map(std::span<const LonLatSite>(window.sites), m);
  }
  if (o.planar) m.frame = OutputFrame::kPlanar;
  std::vector<Site> sites;
  if (!o.sites_path.empty()) {
    sites = io::read_sites(o.sites_path).sites;
    const double scale = o.unit == "km" ? 1000.0 : 1.0;
    for (auto& s : sites) {
      s.x *= scale;
      s.y *= scale;
    }
  } else {
    RandomSitesOptions r;
    r.count = o.random_count;
    r.width_m = o.random_area_km.at(0) * 1000.0;
    r.height_m = o.random_area_km.at(1) * 1000.0;
    r.weight_ratio = o.random_weight_ratio;
    r.seed = o.map.seed;
    sites = random_sites(r);
  }
  return generate_coverage_map(std::span<const Site>(sites), m);
}

std::string summary(const CoverageMap& map, const std::string& dir, double seconds) {
  const CoverageMapCounts& c = map.counts;
  std::ostringstream out;
  out << "covmap-make-map: " << c.sensors << " sensors (" << c.gross_errors << " with gross errors, "
      << c.sensors_without_bins << " serving no bin), " << map.raster.grid.nx << " x " << map.raster.grid.ny
      << " bins of " << map.raster.grid.bin << " m (" << c.covered_bins << " covered), " << c.cells << " cells, "
      << c.holes << " holes, " << c.vertices << " vertices, ";
  if (map.propagation.model != PropagationModel::kMultiplicative)
    out << to_string(map.propagation.model) << " model, ";
  if (map.options.frame == OutputFrame::kLonLat) out << "lon/lat (" << map.projection->description() << ")";
  else out << "plane metres";
  out << " -> " << dir << " in " << seconds << " s (raster " << map.timings.raster_seconds << " s, polygons "
      << map.timings.polygons_seconds << " s)\n";
  return out.str();
}

}  // namespace

int run_make_map(const MakeMapOptions& options) {
  try {
    const auto start = std::chrono::steady_clock::now();
    const CoverageMap map = make(options);
    try {
      write_coverage_map(map, options.output_dir);
    } catch (const std::exception& e) {
      std::cerr << "covmap-make-map: " << e.what() << "\n";
      return kMakeMapCannotWrite;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!options.quiet) std::cout << summary(map, options.output_dir, seconds);
    return kMakeMapOk;
  } catch (const io::InputError& e) {
    std::cerr << "covmap-make-map: " << e.what() << "\n";
    return kMakeMapBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "covmap-make-map: " << e.what() << "\n";
    return kMakeMapBadInput;
  } catch (const std::exception& e) {
    std::cerr << "covmap-make-map: error: " << e.what() << "\n";
    return kMakeMapInternal;
  }
}

}  // namespace covmap::mapgen
