// The map picture of report.html (internal to io/, declared here so tests can check the pieces).
//
// The picture is an inline <svg> whose user units are a grid of AuditRenderOptions::html_grid_px
// pixels: every coordinate is an integer, y points down, and the view is the map's bounding box
// widened by html_margin. Polylines and rings are rounded to that grid, consecutive repeats
// dropped, and simplified (Douglas-Peucker, html_simplify_px), then written as relative path
// commands, so the size of the picture follows what can be seen rather than the vertex count of
// the map. Stroke widths stay in screen pixels (vector-effect: non-scaling-stroke), so zooming in
// by changing the viewBox keeps lines thin.
//
// Drawn, bottom to top: the map's cells (fill per sensor, site_colour of the sensor's index in
// AuditResult::sensors, hover title = sensor); the reported sensors' diagram, dashed, hidden
// until switched on; the recomputed diagram's frame and boundaries; arrows from reported to
// reconstructed positions coloured by verdict; reported positions as rings; reconstructed sensors
// as dots coloured by verdict, with a hover title. Elements more than kFarAway views away from
// the map are left out (they cannot be seen; the sensor table still lists them), and so are arcs
// with an end at infinity (only an unclipped diagram has them).
#pragma once

#include <cstdint>
#include <iosfwd>
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

// SVG path data of one simplified polyline ("M12 5l3-4 0 7" plus "z" when closed): an absolute
// move, then relative line segments.
std::string grid_path(std::span<const GridPoint> points, bool closed);

// The <svg id="map"> element with everything above.
void write_audit_map_svg(const AuditReportContext& context, std::ostream& out);

// Verdict colours shared by the map, the cards, the legend and the table: green consistent, red
// inconsistent, grey undetermined, orange not in map, blue unreported.
std::string verdict_colour(audit::SensorVerdict verdict);
// A CSS class name for the verdict: "v-" and its report name with '-' for '_' ("v-consistent",
// "v-not-in-map", ...).
std::string verdict_class(audit::SensorVerdict verdict);

}  // namespace covmap::report::detail
