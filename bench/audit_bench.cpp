// audit_bench: accuracy and speed of `covmap audit` on generated maps (docs/ACCURACY.md,
// docs/PERFORMANCE.md). For each configuration it generates a best-server map of random sensors
// (tools/mapgen), runs the whole pipeline in memory through the same readers as the program
// (map and sensors written as GeoJSON and read back), and compares with the truth:
//   position error of every sensor owning ≥ 20 bins, in bins and in mean sensor spacings;
//   weight error (log ratio after removing the common factor) in dB (alpha = 3.5);
//   precision and recall of the sensors flagged inconsistent against those given gross errors;
//   wall time of the audit (reading excluded) and of its stages as reported.
// Measures only; nothing asserts.
//
//   audit_bench --n 100 --bin 100 --digits 1 --jitter 5 --seeds 3 [--lonlat] [--json]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "tools/mapgen/coverage_map_files.h"
#include "tools/mapgen/coverage_map_generator.h"
#include "tools/mapgen/site_layouts.h"
#include "io/coverage_map.h"
#include "io/reported_sensors.h"
#include "audit/audit.h"

namespace {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  using namespace covmap;
  CLI::App app{"accuracy and speed of covmap audit on generated maps"};
  int n = 100, seeds = 3;
  double bin = 100.0, jitter = 0.0, spacing = 2000.0, gross = 0.1, ratio = 3.0, alpha = 3.5;
  int digits = 1;
  bool lonlat = false, json_out = false;
  app.add_option("--n", n, "sensors");
  app.add_option("--bin", bin, "raster bin size (m)");
  app.add_option("--digits", digits, "decimal digits of the coordinates (metres; lon/lat: +5)");
  app.add_option("--jitter", jitter, "vertex jitter sigma (m)");
  app.add_option("--spacing", spacing, "mean sensor spacing (m): the square side is spacing·sqrt(n)");
  app.add_option("--gross", gross, "fraction of reported sensors with gross errors");
  app.add_option("--ratio", ratio, "largest / smallest weight");
  app.add_option("--seeds", seeds, "repetitions (seeds 1..k)");
  app.add_flag("--lonlat", lonlat, "write the map in lon/lat (centre 8.5E 47.3N)");
  app.add_flag("--json", json_out, "one JSON object per configuration");
  CLI11_PARSE(app, argc, argv);

  std::vector<double> pos_bins, pos_spacing, weight_db, seconds;
  nlohmann::json stages = nlohmann::json::array();
  int gross_total = 0, gross_flagged = 0, flagged_total = 0, judged = 0;
  double iou_sum = 0.0;
  std::size_t cells = 0, vertices = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    mapgen::RandomSitesOptions ro;
    ro.count = n;
    ro.width_m = ro.height_m = spacing * std::sqrt(static_cast<double>(n));
    ro.weight_ratio = ratio;
    ro.seed = static_cast<std::uint64_t>(seed);
    const auto sites = mapgen::random_sites(ro);
    mapgen::CoverageMapOptions o;
    o.bin_size_m = bin;
    o.vertex_jitter_m = jitter;
    o.errors.gross_fraction = gross;
    o.alpha = alpha;
    o.seed = static_cast<std::uint64_t>(seed);
    if (lonlat) {
      o.frame = mapgen::OutputFrame::kLonLat;
      o.centre = io::LonLat{8.5, 47.3};
      o.coordinate_digits = digits + 5;
    } else {
      o.coordinate_digits = digits;
    }
    const mapgen::CoverageMap generated = mapgen::generate_coverage_map(sites, o);
    const fs::path dir = fs::temp_directory_path() / ("covmap-audit-bench-" + std::to_string(std::random_device{}()));
    mapgen::write_coverage_map(generated, dir);
    io::CoverageMapOptions mo;
    mo.planar = !lonlat;
    const io::CoverageMap map = io::read_coverage_map(dir / mapgen::kMapFileName, mo);
    io::ReportedSensorOptions so;
    so.alpha = alpha;
    so.planar = !lonlat;
    so.projection = map.projection ? &*map.projection : nullptr;
    std::vector<ReportedSensor> reported;
    reported = io::read_reported_sensors(dir / mapgen::kSensorsFileName, so);
    fs::remove_all(dir);
    cells += map.cells.size();
    vertices += map.vertex_count;
    audit::AuditOptions ao;
    ao.alpha = alpha;
    const auto t0 = std::chrono::steady_clock::now();
    const audit::AuditResult r = audit::audit(map.cells, reported, ao);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    iou_sum += r.refined_agreement.mean_iou;
    for (const auto& m : r.messages)
      if (m.find("phase ") != std::string::npos) stages.push_back(m);
    for (const auto& t : r.timings) stages.push_back(t.stage + " took " + std::to_string(t.seconds) + " s");
    stages.push_back(r.refinement_summary);
    std::map<std::string, const mapgen::TrueSensor*> truth;
    for (const auto& t : generated.truth) truth[t.id] = &t;
    std::map<std::string, bool> is_gross;
    for (const auto& s : generated.reported) is_gross[s.id] = s.error.gross != mapgen::GrossErrorKind::kNone;
    // Weights: compare log ratios after removing their median (the common factor is free).
    std::vector<double> logr;
    for (const auto& s : r.sensors)
      if (s.in_map && truth.count(s.id) && truth[s.id]->bins >= 20) logr.push_back(std::log(s.weight / truth[s.id]->weight));
    std::vector<double> sorted = logr;
    const double offset = quantile(sorted, 0.5);
    for (const auto& s : r.sensors) {
      if (!s.in_map || !truth.count(s.id)) continue;
      const auto& t = *truth[s.id];
      if (t.bins >= 20) {
        Point p = s.position;
        if (generated.projection) {
          const auto ll = map.projection->inverse(p);
          p = generated.projection->forward(ll.lon, ll.lat);
        }
        const double e = std::hypot(p.x - t.position.x, p.y - t.position.y);
        pos_bins.push_back(e / bin);
        pos_spacing.push_back(e / spacing);
        weight_db.push_back(std::abs(10.0 * alpha * (std::log(s.weight / t.weight) - offset) / std::log(10.0)));
      }
      if (!s.reported || s.verdict == audit::SensorVerdict::kUndetermined) continue;
      ++judged;
      const bool flagged = s.verdict == audit::SensorVerdict::kInconsistent;
      flagged_total += flagged;
      if (is_gross[s.id]) ++gross_total, gross_flagged += flagged;
    }
  }
  const double precision = flagged_total ? static_cast<double>(gross_flagged) / flagged_total : NAN;
  const double recall = gross_total ? static_cast<double>(gross_flagged) / gross_total : NAN;
  nlohmann::json row = {{"n", n},
                        {"bin_m", bin},
                        {"digits", digits},
                        {"jitter_m", jitter},
                        {"spacing_m", spacing},
                        {"lonlat", lonlat},
                        {"seeds", seeds},
                        {"cells_per_map", static_cast<double>(cells) / seeds},
                        {"vertices_per_map", static_cast<double>(vertices) / seeds},
                        {"pos_err_bins_median", quantile(pos_bins, 0.5)},
                        {"pos_err_bins_p90", quantile(pos_bins, 0.9)},
                        {"pos_err_bins_max", quantile(pos_bins, 1.0)},
                        {"pos_err_spacing_median", quantile(pos_spacing, 0.5)},
                        {"weight_err_db_median", quantile(weight_db, 0.5)},
                        {"weight_err_db_p90", quantile(weight_db, 0.9)},
                        {"weight_err_db_max", quantile(weight_db, 1.0)},
                        {"mean_iou", iou_sum / seeds},
                        {"judged", judged},
                        {"gross", gross_total},
                        {"flagged", flagged_total},
                        {"precision", precision},
                        {"recall", recall},
                        {"audit_s_median", quantile(seconds, 0.5)},
                        {"stages", stages}};
  if (json_out) {
    std::cout << row.dump() << "\n";
  } else {
    for (auto& [k, v] : row.items()) std::cout << k << ": " << v.dump() << "\n";
  }
  return 0;
}
