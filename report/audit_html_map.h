// The map geometry of report.html (internal to report/, declared here so tests can check the
// pieces): the map's cells, the recomputed diagrams and the sensors, rounded to a grid and
// simplified to what a screen can show, for the page's canvas (report/html/report.js draws them).
//
// The grid: the map's bounding box widened by render.html_margin, html_width_px wide at the
// nominal size, in units of html_grid_px pixels; every coordinate is an integer, x to the right,
// y down. Rings and polylines are rounded to it, consecutive repeats dropped, simplified
// (Douglas-Peucker, html_simplify_px) and written as flat integer arrays [x0, y0, dx1, dy1, ...]
// (the first point absolute, then steps), so the page's size follows what can be seen rather than
// the map's vertex count, and a large raster map stays a small page. Pieces more than
// kFarAway views away from the map, or through infinity (only unclipped diagrams have them), are
// left out whole; the sensor table still lists every sensor.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "report/audit_report.h"

namespace covmap::report::detail {

struct GridPoint {
  std::int64_t x = 0;
  std::int64_t y = 0;
  bool operator==(const GridPoint&) const = default;
};

// Douglas-Peucker: the points of `points` to keep so that every dropped point lies within
// `tolerance` of the kept polyline (of the kept closed ring when `closed`). Open polylines keep
// both ends; consecutive repeats are dropped first. A closed ring that keeps fewer than three
// points, or an open one that shrinks to a single point, comes back empty.
std::vector<GridPoint> simplify(std::span<const GridPoint> points, double tolerance, bool closed);

// [x0, y0, x1 - x0, y1 - y0, ...]: one polyline or implicitly closed ring as the page reads it.
std::vector<std::int64_t> delta_encode(std::span<const GridPoint> points);

// The grid of one report: map units to grid units and back.
struct GridFrame {
  double xmin = 0.0, ymax = 0.0;
  double scale = 1.0;  // grid units per map unit
  std::int64_t width = 1, height = 1;

  GridPoint at(Point p) const;
  Point map_point(double gx, double gy) const;  // the inverse of at(), without rounding
  bool drawable(Point p) const;                 // finite and within kFarAway views of the map
};

GridFrame grid_frame(const AuditReportContext& context);

// Every ring of a cell (outer rings and holes alike: the page fills with the even-odd rule), or
// every arc of a diagram that is (frame) or is not (!frame) part of its clip frame, encoded as
// above; empty pieces are left out.
std::vector<std::vector<std::int64_t>> cell_rings(const GridFrame& f, const AuditRenderOptions& o, const io::MapCell& cell);
std::vector<std::vector<std::int64_t>> diagram_arcs(const GridFrame& f, const AuditRenderOptions& o, const Diagram& d,
                                                    bool frame);

// Verdict colours shared by the map, the cards, the legend and the table: green consistent, red
// inconsistent, grey undetermined, orange not in map, blue unreported, purple model misfit.
std::string verdict_colour(audit::SensorVerdict verdict);
// The verdict's position in audit::kAllSensorVerdicts (the page's data refers to verdicts by it).
std::size_t verdict_index(audit::SensorVerdict verdict);
// A CSS class name for the verdict: "v-" and its report name with '-' for '_' ("v-consistent",
// "v-not-in-map", ...).
std::string verdict_class(audit::SensorVerdict verdict);

}  // namespace covmap::report::detail
