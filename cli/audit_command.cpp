#include "cli/audit_command.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

#include "cli/cli_support.h"
#include "report/audit_report.h"
#include "io/atomic_file.h"
#include "io/coverage_map.h"
#include "io/reported_sensors.h"
#include "audit/audit.h"

namespace covmap::cli {

void setup_audit(CLI::App& app, AuditCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand("audit", "Audit a coverage map against its sensors; write reports to a directory");
  cmd->add_option("map", options.map_path, "coverage map: GeoJSON FeatureCollection of (Multi)Polygon cells")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--sensors", options.sensors_path, "reported sensors: covmap.sites/1 JSON, CSV or GeoJSON Points")
      ->check(CLI::ExistingFile);
  cmd->add_option("--alpha", options.alpha, "path-loss exponent (weight = 10^(P/(10·alpha))); enables dB")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--sensor-property", options.sensor_property, "feature property naming the serving sensor")
      ->capture_default_str();
  cmd->add_flag("--planar", options.planar, "coordinates are planar metres, not lon/lat");
  cmd->add_option("--snap", options.snap, "how far apart two cells' copies of a boundary may be (map units; 0 = estimate)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("-o,--output", options.output_dir, "output directory (created or replaced as a whole)")->required();
  cmd->add_flag("-q,--quiet", options.quiet, "no progress messages");
  cmd->add_option("--threads", options.threads, "refinement threads (1 gives the same numbers on every run)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd->callback([&options]() { std::exit(run_audit(options)); });
}

int run_audit(const AuditCommandOptions& options) {
  return guarded([&]() {
    const auto t0 = std::chrono::steady_clock::now();
    auto say = [&](const std::string& what) {
      if (options.quiet) return;
      std::cerr << "covmap audit: " << what << " ("
                << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s)\n";
    };
    say("reading the map");
    io::CoverageMapOptions mo;
    mo.sensor_property = options.sensor_property;
    mo.planar = options.planar;
    const io::CoverageMap map = io::read_coverage_map(options.map_path, mo);
    std::vector<ReportedSensor> reported;
    if (!options.sensors_path.empty()) {
      io::ReportedSensorOptions so;
      so.alpha = options.alpha;
      so.planar = options.planar;
      so.projection = map.projection ? &*map.projection : nullptr;
      reported = io::read_reported_sensors(options.sensors_path, so);
    }
    say("map read: " + std::to_string(map.cells.size()) + " cells, " + std::to_string(map.vertex_count) + " vertices");
    audit::AuditOptions ao;
    ao.alpha = options.alpha;
    ao.cleaning.snap_distance = options.snap;
    ao.threads = options.threads;
    ao.progress = [&](const std::string& stage, double f) { say(stage + ", " + std::to_string(static_cast<int>(100 * f)) + " %"); };
    const audit::AuditResult result = audit::audit(map.cells, reported, ao);
    report::AuditReportContext context{result, map, options.map_path, options.sensors_path, options.alpha,
                                   options.command_line, &ao};
    std::ostringstream json, html, sensors, diagram;
    say("writing report.json");
    report::write_audit_json(context, json);
    say("writing report.html");
    report::write_audit_html(context, html);
    say("writing sensors.geojson");
    report::write_sensors_geojson(context, sensors);
    say("writing diagram.geojson");
    report::write_diagram_geojson(context, diagram);
    say("moving the reports into place");
    io::write_directory_atomically(options.output_dir, {{"report.json", json.str()},
                                         {"report.html", html.str()},
                                         {"sensors.geojson", sensors.str()},
                                         {"diagram.geojson", diagram.str()}});
    const report::AuditVerdictCounts counts = report::count_verdicts(result.sensors);
    std::cout << options.map_path << ": " << result.cleaned.sensors.size() << " sensors in the map, "
              << counts.reported << " reported: " << counts.consistent << " consistent, " << counts.inconsistent
              << " inconsistent, " << counts.not_in_map << " not in the map; refined diagram agrees with the map on "
              << 100.0 * result.refined_agreement.mean_iou << " % of its area";
    if (result.reported_agreement)
      std::cout << " (reported sensors: " << 100.0 * result.reported_agreement->mean_iou << " %)";
    std::cout << " -> " << options.output_dir << "\n";
    for (const auto& s : result.sensors)
      if (s.verdict == audit::SensorVerdict::kInconsistent) std::cout << "  " << s.id << ": " << s.reason << "\n";
    return kOk;
  });
}

}  // namespace covmap::cli
