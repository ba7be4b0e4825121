// A hand-made audit for the report writer tests (audit_*_test.cpp): a real clipped MWVD of a few
// sensors, and sensor audits covering every verdict. Nothing here comes from the writers.
#pragma once

#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "report/audit_report.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::report::testing {

// The map's frame: 1000 m x 800 m, counter-clockwise.
inline std::vector<Point> audit_frame() { return {{0, 0}, {1000, 0}, {1000, 800}, {0, 800}}; }
inline constexpr double kFrameArea = 1000.0 * 800.0;

// Heavy 'b' in the middle; light 'a' and 'd' get Apollonius disks entirely inside the frame (holes
// in b's region: a's circle has radius 4 * 400 / 15 ≈ 107 around (173, 400), d's 4 * 250 / 15 ≈ 67
// around (600, 667)); 'c''s disk crosses the frame's corner.
inline std::vector<Site> holes_sites(const std::string& a_id = "a") {
  return {{a_id, 200, 400, 1.0}, {"b", 600, 400, 4.0}, {"c", 900, 150, 2.0}, {"d", 600, 650, 1.0}};
}

// 'a''s disk (radius 2 * 650 / 3 ≈ 433 around (283, 400)) crosses the frame from bottom to top, so
// heavy 'b' (outside the frame) keeps three pieces: two left corners and the right part.
inline std::vector<Site> pieces_sites() { return {{"a", 500, 400, 1.0}, {"b", 1150, 400, 2.0}}; }

inline Diagram clipped_diagram(const std::vector<Site>& sites) {
  return voronoi::clip_diagram(voronoi::build_diagram(sites), audit_frame());
}

// A rectangle as a map cell polygon (counter-clockwise), with an optional hole (clockwise).
inline io::MapPolygon rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

struct AuditFixture {
  audit::AuditResult result;
  io::CoverageMap map;
  audit::AuditOptions options;
};

inline audit::SensorAudit sensor(const Site& site) {
  audit::SensorAudit s;
  s.id = site.id;
  s.position = {site.x, site.y};
  s.weight = site.weight / 4.0;
  return s;
}

// Sensors: a consistent, b inconsistent, c unreported, d consistent, e reported but not in the map.
// geographic: the map was lon/lat near 8°E 47.1°N.
inline AuditFixture audit_fixture(bool geographic, const std::string& a_id = "a") {
  AuditFixture f;
  const auto sites = holes_sites(a_id);
  f.result.refined_diagram = clipped_diagram(sites);

  auto a = sensor(sites[0]);
  a.tx_power_dbm = 30.0;
  a.sigma_x = 3.0, a.sigma_y = 4.0, a.cov_xy = 1.5, a.sigma_position_m = 4.5, a.sigma_log_weight = 0.05;
  a.uncertainty_available = true;
  a.reported = ReportedSensor{.id = a_id, .position = {203.0, 396.0}, .weight = 0.27, .tx_power_dbm = 30.5, .position_sigma_m = 10.0, .power_sigma_db = 1.0};
  a.position_error_m = 5.0;
  a.power_error_db = 0.5;
  a.weight_ratio = 1.08;
  a.chi2 = 1.25;
  a.verdict = audit::SensorVerdict::kConsistent;
  a.reason = "within 1.1 sigma";
  a.iou_refined = 0.98;
  a.iou_reported = 0.95;

  auto b = sensor(sites[1]);
  b.tx_power_dbm = 42.0;
  b.sigma_x = 2.0, b.sigma_y = 2.0, b.sigma_position_m = 2.0, b.sigma_log_weight = 0.02;
  b.uncertainty_available = true;
  b.reported = ReportedSensor{.id = "b", .position = {680.0, 340.0}, .weight = 1.0, .tx_power_dbm = 48.5};
  b.position_error_m = 100.0;
  b.power_error_db = 6.5;
  b.weight_ratio = 1.9;
  b.chi2 = 412.0;
  b.verdict = audit::SensorVerdict::kInconsistent;
  b.reason = "moved 100 m where 2 m is expected";
  b.iou_refined = 0.99;
  b.iou_reported = 0.71;

  auto c = sensor(sites[2]);  // unreported, no uncertainty
  c.iou_refined = 0.97;

  auto d = sensor(sites[3]);
  d.uncertainty_available = true;
  d.sigma_position_m = 7.0;
  d.reported = ReportedSensor{.id = "d", .position = {598.0, 655.0}, .weight = 0.25};
  d.position_error_m = std::hypot(2.0, 5.0);
  d.chi2 = 0.4;
  d.verdict = audit::SensorVerdict::kConsistent;
  d.reason = "within 0.6 sigma";

  audit::SensorAudit e;
  e.id = "e";
  e.in_map = false;
  e.reported = ReportedSensor{.id = "e", .position = {50.0, 60.0}, .weight = 0.5};
  e.verdict = audit::SensorVerdict::kNotInMap;
  e.reason = "no cell of the map names this sensor";

  f.result.sensors = {a, b, c, d, e};
  f.result.bin_size_m = 10.0;
  f.result.boundary_samples = 1234;
  f.result.refinement_summary = "converged after 12 iterations";
  f.result.messages = {"cleaning: 3 gaps closed", "fit: 1 sensor without uncertainty"};
  f.result.seconds = 0.75;
  f.result.timings = {{"cleaning and starting values", 0.25}, {"refinement", 0.5}};
  f.result.refined_agreement = {0.975, 12.5, {}, {"ghost"}};
  f.result.reported_agreement = audit::DiagramAgreement{0.91, 85.0, {"c"}, {}};
  f.result.reported_diagram = f.result.refined_diagram;
  auto& report = f.result.cleaned.report;
  report.snap_distance = 15.0;
  report.bin_size_estimate = 10.0;
  report.input_vertices = 400;
  report.cells = 4;
  report.sensors = 4;
  report.chains = 9;
  report.frame_chains = 5;
  report.junctions = 6;
  report.junctions_merged = 2;
  report.gaps_closed = 3;
  report.overlaps_resolved = 5;
  report.short_chains_dropped = 7;
  report.nodes_snapped = 11;

  // The map's cells: coarse rectangles standing in for the raster (the writers draw, not judge).
  io::MapCell ca{a_id, 0, {rectangle(0, 0, 400, 800)}};
  ca.polygons[0].holes.push_back({{100, 100}, {100, 200}, {200, 200}, {200, 100}});
  io::MapCell cb{"b", 1, {rectangle(400, 0, 800, 600)}};
  io::MapCell cc{"c", 2, {rectangle(800, 0, 1000, 400), rectangle(800, 400, 1000, 800)}};
  io::MapCell cd{"d", 3, {rectangle(400, 600, 800, 800)}};
  f.map.cells = {ca, cb, cc, cd};
  f.map.vertex_count = 24;
  if (geographic) {
    f.map.frame = std::make_shared<io::LocalProjection>(io::LocalProjection::about(8.0, 47.1));
    f.map.max_scale_distortion = 1.25e-8;
  }
  f.options.inconsistency_chi2 = 16.27;
  f.options.position_floor_bins = 0.5;
  f.options.power_floor_db = 0.5;
  f.options.alpha = 3.5;
  return f;
}

// The fixture plus sensor 'u': in the map and reported, but undetermined, so never judged by the
// χ² test (chi2 unset): the reports must count it as undetermined, never as "other" with
// χ² = 0.
inline AuditFixture audit_fixture_with_undetermined(bool geographic) {
  AuditFixture f = audit_fixture(geographic);
  audit::SensorAudit u;
  u.id = "u";
  u.position = {300.0, 700.0};
  u.weight = 0.2;
  u.reported = ReportedSensor{.id = "u", .position = {310.0, 690.0}, .weight = 0.2};
  u.position_error_m = std::hypot(10.0, 10.0);
  u.verdict = audit::SensorVerdict::kUndetermined;
  u.reason = "the map does not determine this sensor (too few boundary points); not judged";
  f.result.sensors.insert(f.result.sensors.begin() + 4, u);  // map sensors first, then reported-only
  return f;
}

// With full-precision coordinates, so that the geometry tests compare positions bit for bit;
// AuditGeoJsonPrecision checks the default rounding against it.
inline AuditReportContext context_of(const AuditFixture& f) {
  AuditReportContext c{.result = f.result,
                       .map = f.map,
                       .map_file = "maps/city.geojson",
                       .sensors_file = "sensors.csv",
                       .alpha = 3.5,
                       .command_line = "covmap audit maps/city.geojson --sensors sensors.csv --alpha 3.5 -o out/",
                       .options = &f.options};
  c.render.full_precision = true;
  return c;
}

// Signed area of a GeoJSON ring (closed: last position = first), positive counter-clockwise.
template <typename Json>
double ring_area(const Json& ring) {
  double twice = 0.0;
  const double x0 = ring[0][0].template get<double>(), y0 = ring[0][1].template get<double>();
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    const double x1 = ring[i][0].template get<double>() - x0, y1 = ring[i][1].template get<double>() - y0;
    const double x2 = ring[i + 1][0].template get<double>() - x0, y2 = ring[i + 1][1].template get<double>() - y0;
    twice += x1 * y2 - x2 * y1;
  }
  return twice / 2.0;
}

// Weighted distance |p - s| / w.
inline double weighted_distance(Point p, const Site& s) {
  return std::hypot(p.x - s.x, p.y - s.y) / s.weight;
}

}  // namespace covmap::report::testing
