// audit_bench: accuracy and speed of `covmap audit` on generated maps (docs/ACCURACY.md,
// docs/PERFORMANCE.md). For each configuration it generates a best-server map (tools/mapgen) of
// random sensors uniform in a square, or of a window of real towns (--towns), under the
// multiplicative model or another propagation model (--model), optionally with a reception limit
// (--max-range); runs the whole pipeline in memory through the same readers as the program (map
// and sensors written as GeoJSON and read back), and compares with the truth:
//   position error of every sensor owning ≥ 20 bins, in bins and in mean sensor spacings;
//   weight error (log ratio after removing the common factor) in dB (alpha = 3.5);
//   precision and recall of the sensors flagged inconsistent against those given gross errors,
//   and how many correctly reported sensors were flagged (the figure that matters for maps of
//   another propagation model, where the audit should blame nobody);
//   the count of every verdict, and the share of sensors whose local spacing (distance to the
//   nearest other sensor) is at least 10 bins (the accuracy targets' condition);
//   wall time of the audit (reading excluded) and of its stages as reported.
// Measures only; nothing asserts.
//
//   audit_bench --n 100 --bin 100 --digits 1 --jitter 5 --seeds 3 [--lonlat] [--json]
//   audit_bench --towns datasets/towns/netherlands.csv --n 120 --bin 0 --model shadowing --gross 0
//               --max-range 8000 --lonlat --seeds 3 --json
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "tools/mapgen/coverage_map_files.h"
#include "tools/mapgen/coverage_map_generator.h"
#include "tools/mapgen/lonlat_sites_csv.h"
#include "tools/mapgen/site_layouts.h"
#include "tools/mapgen/town_layouts.h"
#include "io/coverage_map.h"
#include "io/reported_sensors.h"
#include "audit/audit.h"

namespace {

using namespace covmap;
namespace fs = std::filesystem;

struct BenchOptions {
  int n = 100, seeds = 3, first_seed = 1, digits = 1;
  double bin = 100.0, jitter = 0.0, spacing = 2000.0, gross = 0.1, ratio = 3.0, alpha = 3.5;
  bool lonlat = false, json_out = false;
  std::string towns;                       // town list: clustered windows of n towns instead of a square
  std::string town_weights = "population";
  std::string model = "multiplicative";
  std::optional<double> max_range;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

// The generated map of one seed: uniform sensors in a square, or a window of real towns.
mapgen::CoverageMap generate(const BenchOptions& b, int seed) {
  mapgen::CoverageMapOptions o;
  if (b.bin > 0.0) o.bin_size_m = b.bin;  // 0: the generator's default (mean spacing / 20)
  o.vertex_jitter_m = b.jitter;
  o.errors.gross_fraction = b.gross;
  o.alpha = b.alpha;
  o.seed = static_cast<std::uint64_t>(seed);
  o.max_range_m = b.max_range;
  o.propagation.model = *mapgen::propagation_model_from_string(b.model);
  o.frame = b.lonlat ? mapgen::OutputFrame::kLonLat : mapgen::OutputFrame::kPlanar;
  o.coordinate_digits = b.lonlat ? b.digits + 5 : b.digits;
  if (!b.towns.empty()) {
    const auto table = mapgen::read_lonlat_sites_csv(b.towns);
    mapgen::TownLayoutOptions t;
    t.count = b.n;
    t.weights = *mapgen::town_weights_from_string(b.town_weights);
    t.alpha = b.alpha;
    t.seed = o.seed;
    const auto window = mapgen::clustered_town_sites(table.sites, t);
    return mapgen::generate_coverage_map(std::span<const mapgen::LonLatSite>(window.sites), o);
  }
  mapgen::RandomSitesOptions ro;
  ro.count = b.n;
  ro.width_m = ro.height_m = b.spacing * std::sqrt(static_cast<double>(b.n));
  ro.weight_ratio = b.ratio;
  ro.seed = o.seed;
  if (b.lonlat) o.centre = io::LonLat{8.5, 47.3};
  return mapgen::generate_coverage_map(mapgen::random_sites(ro), o);
}

std::vector<Site> true_sites(const mapgen::CoverageMap& m) {
  std::vector<Site> sites;
  for (const auto& t : m.truth) sites.push_back(Site{t.id, t.position.x, t.position.y, t.weight});
  return sites;
}

// Share of sensors whose nearest other sensor is at least 10 bins away.
double share_spaced_10_bins(const std::vector<Site>& sites, double bin) {
  std::size_t ok = 0;
  for (const auto& a : sites) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& c : sites)
      if (&a != &c) nearest = std::min(nearest, std::hypot(a.x - c.x, a.y - c.y));
    ok += nearest >= 10.0 * bin;
  }
  return static_cast<double>(ok) / static_cast<double>(sites.size());
}

// A resolved cell (bins at most 1/10 of the local spacing: about 10 bins across), as in the
// bundled-maps test (tests/cli/bundled_maps_truth_test.py) and docs/ACCURACY.md.
constexpr std::size_t kResolvedBins = 100;

struct SensorErrorSizes {
  double position_m = 0.0, power_db = 0.0;
};
// The gross part of a reported sensor's error.
SensorErrorSizes error_sizes(const mapgen::ReportedSensor& r) {
  return {std::hypot(r.error.gross_offset.x, r.error.gross_offset.y), std::abs(r.error.gross_power_db)};
}

struct Tally {
  std::vector<double> pos_bins, pos_spacing, weight_db, seconds, spaced;
  nlohmann::json stages = nlohmann::json::array();
  std::map<std::string, int> verdicts;
  int gross_total = 0, gross_flagged = 0, flagged_total = 0, judged = 0, correct_flagged = 0;
  // The accuracy targets (docs/ACCURACY.md): over sensors whose cell has ≥ kResolvedBins bins,
  // position and weight RMSE, undetermined share; recall of the gross errors such a map can reveal
  // (≥ 5 bins or ≥ 5 dB, on a resolved cell); maps reported as model misfits.
  double pos_sq = 0.0, weight_sq = 0.0;
  int resolved = 0, undetermined = 0, with_cell = 0, revealable = 0, revealed = 0, misfit_maps = 0, misfit_verdicts = 0;
  double iou_sum = 0.0, bin_sum = 0.0;
  std::size_t cells = 0, vertices = 0;
};

// Audits one generated map and adds its figures to the tally.
void audit_one(const BenchOptions& b, const mapgen::CoverageMap& generated, Tally& tally) {
  const fs::path dir = fs::temp_directory_path() / ("covmap-audit-bench-" + std::to_string(std::random_device{}()));
  mapgen::write_coverage_map(generated, dir);
  io::CoverageMapOptions mo;
  mo.planar = !b.lonlat;
  const io::CoverageMap map = io::read_coverage_map(dir / mapgen::kMapFileName, mo);
  io::ReportedSensorOptions so;
  so.alpha = b.alpha;
  so.planar = !b.lonlat;
  so.frame = map.frame ? &*map.frame : nullptr;
  const std::vector<ReportedSensor> reported = io::read_reported_sensors(dir / mapgen::kSensorsFileName, so);
  fs::remove_all(dir);
  tally.cells += map.cells.size();
  tally.vertices += map.vertex_count;
  audit::AuditOptions ao;
  ao.alpha = b.alpha;
  const auto t0 = std::chrono::steady_clock::now();
  const audit::AuditResult r = audit::audit(map.cells, reported, ao);
  tally.seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  tally.iou_sum += r.refined_agreement.mean_iou;
  tally.misfit_maps += r.model_fit.misfit;
  for (const auto& m : r.messages)
    if (m.find("phase ") != std::string::npos) tally.stages.push_back(m);
  for (const auto& t : r.timings) tally.stages.push_back(t.stage + " took " + std::to_string(t.seconds) + " s");
  tally.stages.push_back(r.refinement_summary);

  const double bin = generated.raster.grid.bin;
  const auto sites = true_sites(generated);
  // Uniform layouts: the nominal spacing of the square (as docs/ACCURACY.md's rows always used);
  // towns: the window's mean nearest-neighbour spacing.
  const double spacing = b.towns.empty() ? b.spacing : mapgen::mean_nearest_neighbour_distance(sites);
  tally.bin_sum += bin;
  tally.spaced.push_back(share_spaced_10_bins(sites, bin));
  std::map<std::string, const mapgen::TrueSensor*> truth;
  for (const auto& t : generated.truth) truth[t.id] = &t;
  std::map<std::string, bool> is_gross;
  for (const auto& s : generated.reported) is_gross[s.id] = s.error.gross != mapgen::GrossErrorKind::kNone;
  // Weights: compare log ratios after removing their median (the common factor is free).
  std::vector<double> logr;
  for (const auto& s : r.sensors)
    if (s.in_map && truth.count(s.id) && truth[s.id]->bins >= 20) logr.push_back(std::log(s.weight / truth[s.id]->weight));
  const double offset = quantile(logr, 0.5);
  std::map<std::string, const mapgen::ReportedSensor*> reported_truth;
  for (const auto& s : generated.reported) reported_truth[s.id] = &s;
  for (const auto& s : r.sensors) {
    ++tally.verdicts[std::string(audit::to_string(s.verdict))];
    tally.misfit_verdicts += s.verdict == audit::SensorVerdict::kModelMisfit;
    if (!s.in_map || !truth.count(s.id)) continue;
    const auto& t = *truth[s.id];
    ++tally.with_cell;
    tally.undetermined += s.verdict == audit::SensorVerdict::kUndetermined;
    if (t.bins >= kResolvedBins) {
      const SensorErrorSizes e = error_sizes(*reported_truth[s.id]);
      if (is_gross[s.id] && (e.position_m >= 5.0 * bin || e.power_db >= 5.0)) {
        ++tally.revealable;
        tally.revealed += s.verdict == audit::SensorVerdict::kInconsistent;
      }
    }
    if (t.bins >= 20) {
      Point p = s.position;
      if (map.frame) {
        const auto ll = map.frame->inverse(p);
        p = generated.projection->forward(ll.lon, ll.lat);
      }
      const double e = std::hypot(p.x - t.position.x, p.y - t.position.y);
      tally.pos_bins.push_back(e / bin);
      tally.pos_spacing.push_back(e / spacing);
      tally.weight_db.push_back(std::abs(10.0 * b.alpha * (std::log(s.weight / t.weight) - offset) / std::log(10.0)));
      if (t.bins >= kResolvedBins) {
        ++tally.resolved;
        tally.pos_sq += (e / bin) * (e / bin);
        tally.weight_sq += tally.weight_db.back() * tally.weight_db.back();
      }
    }
    if (!s.reported || s.verdict == audit::SensorVerdict::kUndetermined) continue;
    ++tally.judged;
    const bool flagged = s.verdict == audit::SensorVerdict::kInconsistent;
    tally.flagged_total += flagged;
    if (is_gross[s.id]) ++tally.gross_total, tally.gross_flagged += flagged;
    else tally.correct_flagged += flagged;
  }
}

nlohmann::json row(const BenchOptions& b, const Tally& t) {
  const double seeds = b.seeds;
  return {{"layout", b.towns.empty() ? "uniform" : fs::path(b.towns).stem().string()},
          {"town_weights", b.towns.empty() ? nlohmann::json(nullptr) : nlohmann::json(b.town_weights)},
          {"model", b.model},
          {"max_range_m", b.max_range ? nlohmann::json(*b.max_range) : nlohmann::json(nullptr)},
          {"n", b.n},
          {"bin_m", t.bin_sum / seeds},
          {"digits", b.digits},
          {"jitter_m", b.jitter},
          {"spacing_m", b.towns.empty() ? nlohmann::json(b.spacing) : nlohmann::json(nullptr)},
          {"lonlat", b.lonlat},
          {"seeds", b.seeds},
          {"share_spaced_10_bins", quantile(t.spaced, 0.5)},
          {"cells_per_map", static_cast<double>(t.cells) / seeds},
          {"vertices_per_map", static_cast<double>(t.vertices) / seeds},
          {"pos_err_bins_median", quantile(t.pos_bins, 0.5)},
          {"pos_err_bins_p90", quantile(t.pos_bins, 0.9)},
          {"pos_err_bins_max", quantile(t.pos_bins, 1.0)},
          {"pos_err_spacing_median", quantile(t.pos_spacing, 0.5)},
          {"weight_err_db_median", quantile(t.weight_db, 0.5)},
          {"weight_err_db_p90", quantile(t.weight_db, 0.9)},
          {"weight_err_db_max", quantile(t.weight_db, 1.0)},
          {"mean_iou", t.iou_sum / seeds},
          {"verdicts", t.verdicts},
          {"judged", t.judged},
          {"gross", t.gross_total},
          {"flagged", t.flagged_total},
          {"correct_flagged", t.correct_flagged},
          {"precision", t.flagged_total ? static_cast<double>(t.gross_flagged) / t.flagged_total : NAN},
          {"recall", t.gross_total ? static_cast<double>(t.gross_flagged) / t.gross_total : NAN},
          {"resolved", t.resolved},
          {"pos_rmse_bins_resolved", t.resolved ? std::sqrt(t.pos_sq / t.resolved) : NAN},
          {"weight_rmse_db_resolved", t.resolved ? std::sqrt(t.weight_sq / t.resolved) : NAN},
          {"undetermined_share", t.with_cell ? static_cast<double>(t.undetermined) / t.with_cell : NAN},
          {"revealable", t.revealable},
          {"recall_revealable", t.revealable ? static_cast<double>(t.revealed) / t.revealable : NAN},
          {"misfit_maps", t.misfit_maps},
          {"model_misfit_verdicts", t.misfit_verdicts},
          {"audit_s_median", quantile(t.seconds, 0.5)},
          {"stages", t.stages}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"accuracy and speed of covmap audit on generated maps"};
  BenchOptions b;
  app.add_option("--n", b.n, "sensors (with --towns: towns in the window)");
  app.add_option("--bin", b.bin, "raster bin size (m); 0: the generator's default, mean spacing / 20");
  app.add_option("--digits", b.digits, "decimal digits of the coordinates (metres; lon/lat: +5)");
  app.add_option("--jitter", b.jitter, "vertex jitter sigma (m)");
  app.add_option("--spacing", b.spacing, "mean sensor spacing (m): the square side is spacing·sqrt(n)");
  app.add_option("--gross", b.gross, "fraction of reported sensors with gross errors");
  app.add_option("--ratio", b.ratio, "largest / smallest weight (uniform layouts)");
  app.add_option("--seeds", b.seeds, "repetitions (seeds first..first+k-1)");
  app.add_option("--first-seed", b.first_seed, "the first seed (default 1)");
  app.add_option("--towns", b.towns, "town list (datasets/towns/*.csv): a window of --n real towns per seed")
      ->check(CLI::ExistingFile);
  app.add_option("--town-weights", b.town_weights, "population | power-classes");
  app.add_option("--model", b.model, "multiplicative | exponents | excess-loss | shadowing");
  app.add_option("--max-range", b.max_range, "reach of the strongest sensor (m): a reception limit");
  app.add_flag("--lonlat", b.lonlat, "write the map in lon/lat (uniform layouts: centre 8.5E 47.3N)");
  app.add_flag("--json", b.json_out, "one JSON object per configuration");
  CLI11_PARSE(app, argc, argv);
  if (!mapgen::propagation_model_from_string(b.model) || !mapgen::town_weights_from_string(b.town_weights)) {
    std::cerr << "audit_bench: unknown --model or --town-weights\n";
    return 2;
  }
  Tally tally;
  for (int seed = b.first_seed; seed < b.first_seed + b.seeds; ++seed) audit_one(b, generate(b, seed), tally);
  const nlohmann::json out = row(b, tally);
  if (b.json_out) {
    std::cout << out.dump() << "\n";
  } else {
    for (auto& [k, v] : out.items()) std::cout << k << ": " << v.dump() << "\n";
  }
  return 0;
}
