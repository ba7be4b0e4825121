#include "tools/mapgen/coverage_map_generator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "tools/mapgen/random_stream.h"
#include "tools/mapgen/raster_polygons.h"
#include "tools/mapgen/received_power_raster.h"
#include "tools/mapgen/site_layouts.h"

namespace covmap::mapgen {
namespace {


bool fail(std::string* why, const std::string& message) {
  if (why) *why = message;
  return false;
}

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

// Problems with the sensors, collected so one message names them all.
class SiteProblems {
 public:
  void add(std::size_t index, const std::string& id, const std::string& message) {
    ++count_;
    if (count_ <= kListed) text_ << "\n  site " << index << " ('" << id << "'): " << message;
  }
  void throw_if_any() const {
    if (count_ == 0) return;
    std::ostringstream out;
    out << "invalid sensors: " << count_ << " problem(s)" << text_.str();
    if (count_ > kListed) out << "\n  ... and " << count_ - kListed << " more";
    throw std::invalid_argument(out.str());
  }

 private:
  static constexpr std::size_t kListed = 20;
  std::size_t count_ = 0;
  std::ostringstream text_;
};

void check_sites(std::span<const Site> sites, SiteProblems& problems) {
  std::map<std::string, std::size_t> ids;
  std::map<std::pair<double, double>, std::size_t> positions;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const Site& s = sites[k];
    if (s.id.empty()) problems.add(k, s.id, "empty id");
    if (const auto [it, fresh] = ids.emplace(s.id, k); !fresh && !s.id.empty())
      problems.add(k, s.id, "id already used by site " + std::to_string(it->second));
    if (!std::isfinite(s.x) || !std::isfinite(s.y)) {
      problems.add(k, s.id, "position must be finite");
    } else if (const auto [it, fresh] = positions.emplace(std::pair{s.x, s.y}, k); !fresh) {
      problems.add(k, s.id, "same position as site " + std::to_string(it->second) + " ('" + sites[it->second].id + "')");
    }
    if (!positive(s.weight)) {
      std::ostringstream msg;
      msg << "weight must be finite and positive (got " << s.weight << ")";
      problems.add(k, s.id, msg.str());
    }
  }
}

double round_to(double value, int digits) {
  const double scale = std::pow(10.0, digits);
  return std::round(value * scale) / scale;
}

// The extent moved outwards to bin multiples, as a raster grid.
RasterGrid make_grid(const Rectangle& extent, double bin, std::size_t max_bins) {
  RasterGrid grid;
  grid.bin = bin;
  grid.x0 = std::floor(extent.xmin / bin) * bin;
  grid.y0 = std::floor(extent.ymin / bin) * bin;
  const double nx = std::max(1.0, std::ceil((extent.xmax - grid.x0) / bin));
  const double ny = std::max(1.0, std::ceil((extent.ymax - grid.y0) / bin));
  if (nx * ny > static_cast<double>(max_bins) || nx > std::numeric_limits<int>::max() / 2 ||
      ny > std::numeric_limits<int>::max() / 2) {
    std::ostringstream msg;
    msg << "the raster would have " << nx << " x " << ny << " bins, more than max_bins = " << max_bins
        << " (use a larger bin or a smaller extent)";
    throw std::invalid_argument(msg.str());
  }
  grid.nx = static_cast<int>(nx);
  grid.ny = static_cast<int>(ny);
  return grid;
}

Rectangle auto_extent(std::span<const Site> sites, double margin) {
  Rectangle r{sites[0].x, sites[0].y, sites[0].x, sites[0].y};
  for (const auto& s : sites) {
    r.xmin = std::min(r.xmin, s.x);
    r.ymin = std::min(r.ymin, s.y);
    r.xmax = std::max(r.xmax, s.x);
    r.ymax = std::max(r.ymax, s.y);
  }
  return {r.xmin - margin, r.ymin - margin, r.xmax + margin, r.ymax + margin};
}

class Generator {
 public:
  Generator(std::span<const Site> sites, const CoverageMapOptions& options, std::span<const io::LonLat> given_lonlat)
      : sites_(sites), given_lonlat_(given_lonlat) {
    out_.options = options;
  }

  CoverageMap run() {
    using Clock = std::chrono::steady_clock;
    const auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
    const auto start = Clock::now();
    resolve_options();
    make_truth();
    const auto raster_start = Clock::now();
    make_raster(make_grid(*opt().extent, *opt().bin_size_m, opt().max_bins));
    out_.timings.raster_seconds = seconds_since(raster_start);
    const auto polygons_start = Clock::now();
    make_features();
    out_.timings.polygons_seconds = seconds_since(polygons_start);
    make_reported();
    count();
    out_.timings.total_seconds = seconds_since(start);
    return std::move(out_);
  }

 private:
  CoverageMapOptions& opt() { return out_.options; }

  void resolve_options() {
    CoverageMapOptions& o = opt();
    if (o.centre) out_.projection = io::LocalProjection::about(o.centre->lon, o.centre->lat);
    if (o.frame == OutputFrame::kLonLat && !out_.projection)
      throw std::invalid_argument("lon/lat output of planar sensors needs a projection centre");
    if (!o.coordinate_digits) o.coordinate_digits = o.frame == OutputFrame::kLonLat ? 6 : 2;
    if (!o.bin_size_m || !o.extent) {
      if (sites_.size() < 2)
        throw std::invalid_argument("a single sensor has no spacing: give both the bin size and the extent");
      const double spacing = mean_nearest_neighbour_distance(sites_);
      if (!o.bin_size_m) o.bin_size_m = default_bin_size(spacing);
      if (!o.extent) o.extent = auto_extent(sites_, o.extent_margin_spacings * spacing);
    }
  }

  void make_truth() {
    double wmax = 0.0;
    for (const auto& s : sites_) wmax = std::max(wmax, s.weight);
    for (std::size_t k = 0; k < sites_.size(); ++k) {
      const Site& s = sites_[k];
      TrueSensor t;
      t.id = s.id;
      t.position = {s.x, s.y};
      t.weight = s.weight / wmax;
      t.tx_power_dbm = power_of(t.weight);
      if (!given_lonlat_.empty()) t.lonlat = given_lonlat_[k];
      else if (out_.projection) t.lonlat = out_.projection->inverse(t.position);
      out_.truth.push_back(t);
      scaled_.push_back(Site{s.id, s.x, s.y, t.weight});
    }
  }

  // Multiplicative: by distance / weight, exactly as the audit's own raster. Other models: by
  // received power, with per-sensor parameters drawn from the seed.
  void make_raster(const RasterGrid& grid) {
    const CoverageMapOptions& o = opt();
    if (o.propagation.model == PropagationModel::kMultiplicative) {
      out_.raster = best_server_raster(scaled_, grid, o.max_range_m);
      return;
    }
    std::vector<Point> positions;
    std::vector<double> powers;
    for (const auto& t : out_.truth) {
      positions.push_back(t.position);
      powers.push_back(t.tx_power_dbm);
    }
    const double spacing = sites_.size() >= 2 ? mean_nearest_neighbour_distance(sites_) : 0.0;
    out_.propagation = draw_propagation(positions, powers, o.alpha, o.propagation, spacing, o.seed);
    if (o.max_range_m) out_.sensitivity_dbm = sensitivity_for_range(o.reference_power_dbm, o.alpha, *o.max_range_m);
    out_.raster = received_power_raster(out_.propagation, grid, out_.sensitivity_dbm);
  }

  double power_of(double weight) const { return 10.0 * out_.options.alpha * std::log10(weight) + out_.options.reference_power_dbm; }

  // Plane metres to what is written, rounded.
  Point output_point(Point p) const {
    const int digits = *out_.options.coordinate_digits;
    if (out_.options.frame == OutputFrame::kLonLat) {
      const io::LonLat g = out_.projection->inverse(p);
      return {round_to(g.lon, digits), round_to(g.lat, digits)};
    }
    return {round_to(p.x, digits), round_to(p.y, digits)};
  }

  void make_features() {
    const auto& raster = out_.raster;
    const auto polygons = raster_polygons(raster.labels, raster.grid.nx, raster.grid.ny, opt().simplify_collinear);
    std::vector<std::vector<const GridPolygon*>> by_sensor(sites_.size());
    for (const auto& p : polygons) by_sensor[static_cast<std::size_t>(p.label)].push_back(&p);

    RandomStream jitter(opt().seed, RandomPurpose::kVertexJitter);
    const double sigma = opt().vertex_jitter_m;
    // Noise per grid corner of one feature: where two rings of a sensor's geometry share a corner
    // (a hole touching the outer ring, two cells meeting diagonally) they keep sharing it, so each
    // feature stays valid geometry, as a tool's export would; different sensors' copies of a corner
    // get independent noise, which makes the gaps and overlaps between neighbours.
    std::map<std::pair<int, int>, Point> noise;
    for (std::size_t k = 0; k < by_sensor.size(); ++k) {
      if (by_sensor[k].empty()) continue;
      noise.clear();
      MapFeature feature;
      feature.sensor = static_cast<int>(k);
      for (const GridPolygon* polygon : by_sensor[k]) {
        MapCell cell;
        cell.bins = polygon->bins;
        out_.truth[k].bins += polygon->bins;
        ++out_.truth[k].cells;
        for (const GridRing& grid_ring : polygon->rings) {
          Ring planar, output;
          for (std::size_t v = 0; v + 1 < grid_ring.size(); ++v) {
            const GridVertex corner = grid_ring[v];
            Point p{raster.grid.corner_x(corner.i), raster.grid.corner_y(corner.j)};
            if (sigma > 0.0) {
              auto [it, fresh] = noise.try_emplace({corner.i, corner.j});
              if (fresh) {
                it->second.x = sigma * jitter.normal();
                it->second.y = sigma * jitter.normal();
              }
              p.x += it->second.x;
              p.y += it->second.y;
            }
            planar.push_back(p);
            output.push_back(output_point(p));
          }
          planar.push_back(planar.front());
          output.push_back(output.front());
          cell.planar.push_back(std::move(planar));
          cell.output.push_back(std::move(output));
        }
        feature.cells.push_back(std::move(cell));
      }
      out_.features.push_back(std::move(feature));
    }
  }

  void make_reported() {
    RandomStream random(opt().seed, RandomPurpose::kSensorErrors);
    const auto errors = draw_sensor_errors(sites_.size(), opt().errors, random);
    for (std::size_t k = 0; k < sites_.size(); ++k) {
      const TrueSensor& t = out_.truth[k];
      ReportedSensor r;
      r.id = t.id;
      r.error = errors[k];
      const Point offset = errors[k].total_offset();
      r.position = {t.position.x + offset.x, t.position.y + offset.y};
      r.output = output_point(r.position);
      r.tx_power_dbm = round_to(t.tx_power_dbm + errors[k].total_power_db(), opt().power_digits);
      r.weight = std::pow(10.0, (r.tx_power_dbm - opt().reference_power_dbm) / (10.0 * opt().alpha));
      out_.reported.push_back(std::move(r));
    }
  }

  void count() {
    CoverageMapCounts& c = out_.counts;
    c.sensors = sites_.size();
    c.bins = out_.raster.labels.size();
    for (const int label : out_.raster.labels) c.covered_bins += label >= 0 ? 1 : 0;
    for (const auto& f : out_.features) {
      c.cells += f.cells.size();
      for (const auto& cell : f.cells) {
        c.holes += cell.output.size() - 1;
        for (const auto& ring : cell.output) c.vertices += ring.size() - 1;
      }
    }
    c.sensors_without_bins = sites_.size() - out_.features.size();
    for (const auto& r : out_.reported) c.gross_errors += r.error.gross != GrossErrorKind::kNone ? 1 : 0;
  }

  std::span<const Site> sites_;
  std::span<const io::LonLat> given_lonlat_;
  std::vector<Site> scaled_;
  CoverageMap out_;
};

void check_options(const CoverageMapOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument("invalid coverage-map options: " + why);
}

}  // namespace

bool CoverageMapOptions::is_valid(std::string* why) const {
  if (bin_size_m && !positive(*bin_size_m)) return fail(why, "bin size must be finite and positive");
  if (extent) {
    const Rectangle& e = *extent;
    if (!std::isfinite(e.xmin) || !std::isfinite(e.ymin) || !std::isfinite(e.xmax) || !std::isfinite(e.ymax) ||
        !(e.xmax > e.xmin) || !(e.ymax > e.ymin))
      return fail(why, "extent must be finite with xmax > xmin and ymax > ymin");
  }
  if (!std::isfinite(extent_margin_spacings) || extent_margin_spacings < 0.0)
    return fail(why, "extent margin must be finite and >= 0");
  if (max_range_m && !positive(*max_range_m)) return fail(why, "maximum range must be finite and positive");
  if (max_bins < 1) return fail(why, "max_bins must be at least 1");
  if (centre && (!std::isfinite(centre->lon) || !std::isfinite(centre->lat) || std::abs(centre->lon) > 180.0 ||
                 std::abs(centre->lat) >= 90.0))
    return fail(why, "centre must have lon in [-180, 180] and lat in (-90, 90)");
  if (coordinate_digits && (*coordinate_digits < 0 || *coordinate_digits > 12))
    return fail(why, "coordinate digits must be in [0, 12]");
  if (power_digits < 0 || power_digits > 6) return fail(why, "power digits must be in [0, 6]");
  if (!std::isfinite(vertex_jitter_m) || vertex_jitter_m < 0.0) return fail(why, "vertex jitter must be finite and >= 0");
  if (!positive(alpha)) return fail(why, "alpha must be finite and positive");
  if (!std::isfinite(reference_power_dbm)) return fail(why, "reference power must be finite");
  std::string error_why;
  if (!errors.is_valid(&error_why)) return fail(why, error_why);
  if (!propagation.is_valid(alpha, &error_why)) return fail(why, error_why);
  return true;
}

double default_bin_size(double mean_spacing) {
  if (!positive(mean_spacing)) throw std::invalid_argument("default_bin_size: spacing must be positive");
  const double target = mean_spacing / 20.0;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (const double step : {5.0, 2.0, 1.0})
    if (step * decade <= target) return step * decade;
  return decade;  // only reached through rounding of log10 at an exact power of ten
}

CoverageMap generate_coverage_map(std::span<const Site> sites, const CoverageMapOptions& options) {
  check_options(options);
  if (sites.empty()) throw std::invalid_argument("invalid sensors: none given");
  SiteProblems problems;
  check_sites(sites, problems);
  problems.throw_if_any();
  return Generator(sites, options, {}).run();
}

CoverageMap generate_coverage_map(std::span<const LonLatSite> sites, const CoverageMapOptions& options) {
  check_options(options);
  if (sites.empty()) throw std::invalid_argument("invalid sensors: none given");
  SiteProblems problems;
  bool usable = true;
  double lon_min = 180.0, lon_max = -180.0, lat_min = 90.0, lat_max = -90.0;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const LonLatSite& s = sites[k];
    if (!std::isfinite(s.lon) || std::abs(s.lon) > 180.0 || !std::isfinite(s.lat) || std::abs(s.lat) >= 90.0) {
      std::ostringstream msg;
      msg << "lon must be in [-180, 180] and lat in (-90, 90) (got " << s.lon << ", " << s.lat << ")";
      problems.add(k, s.id, msg.str());
      usable = false;
      continue;
    }
    lon_min = std::min(lon_min, s.lon);
    lon_max = std::max(lon_max, s.lon);
    lat_min = std::min(lat_min, s.lat);
    lat_max = std::max(lat_max, s.lat);
  }
  if (!usable) problems.throw_if_any();
  CoverageMapOptions resolved = options;
  if (!resolved.centre) resolved.centre = io::LonLat{0.5 * (lon_min + lon_max), 0.5 * (lat_min + lat_max)};
  const io::LocalProjection projection = io::LocalProjection::about(resolved.centre->lon, resolved.centre->lat);
  std::vector<Site> planar;
  std::vector<io::LonLat> given;
  for (const auto& s : sites) {
    const Point p = projection.forward(s.lon, s.lat);
    planar.push_back(Site{s.id, p.x, p.y, s.weight});
    given.push_back({s.lon, s.lat});
  }
  // Same positions in lon/lat are same positions in the plane; the planar check names them.
  check_sites(planar, problems);
  problems.throw_if_any();
  CoverageMap map = Generator(planar, resolved, given).run();
  for (std::size_t k = 0; k < sites.size(); ++k) map.truth[k].name = sites[k].name;  // labels only
  return map;
}

}  // namespace covmap::mapgen
