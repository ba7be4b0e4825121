// covmap::report audit reports: the five files `covmap audit MAP -o OUTDIR/` writes from an
// AuditResult (audit/audit.h) and the map it audited (io/coverage_map.h). docs/FORMATS.md,
// "Audit reports", documents every member and property.
//
//   report.json      write_audit_json       covmap.audit/1: every number of the audit, for programs
//   sensors.geojson  write_sensors_geojson  reconstructed sensors (Points), for GIS
//   shifts.geojson   write_shifts_geojson   reported → reconstructed positions (LineStrings): a file
//                                           of its own, as formats like the Shapefile take one
//                                           geometry type per layer
//   diagram.geojson  write_diagram_geojson  the recomputed diagram, one (Multi)Polygon per sensor
//   report.html      write_audit_html       one self-contained page for people
//
// Contract
//  - Accepted: any AuditResult, including partial ones (a failed stage leaves defaults behind) and
//    non-finite numbers; any strings (ids may hold markup, quotes, control characters or bytes
//    that are not UTF-8). The map's cells are planar metres; map.frame set means the map was
//    lon/lat and geographic output is wanted. result.refined_diagram is expected clipped to the
//    map (all its faces bounded); unbounded faces are left out of diagram.geojson and the HTML and
//    counted (diagram.geojson's "omitted_unbounded_faces").
//  - Guaranteed: valid JSON (RFC 8259) and GeoJSON (RFC 7946) whose numbers are the doubles of the
//    result in the shortest form that reads back to the same bits, except the GeoJSON coordinates:
//    rounded to 1e-8 degrees (geographic) or 1e-3 map units (planar) unless render.full_precision; a NaN or infinite value is
//    written as null, never as a number. Strings that are not UTF-8 have the bad bytes replaced by
//    U+FFFD. Geographic output is [lon, lat] on WGS84 through the map's LocalProjection; planar
//    output is [x, y] in the map's metres. Polygon rings are closed (last position = first), outer
//    rings counter-clockwise and holes clockwise, with at least 4 positions. The HTML needs no
//    network (CSS, JavaScript and SVG inline, no URL), HTML-escapes every string that came from
//    input, and rounds its picture to render.html_grid_px so its size follows what can be seen,
//    not the map's vertex count.
//  - Rejected: invalid render options (AuditRenderOptions::is_valid) throw std::invalid_argument
//    before anything is written. Stream failures are the caller's to check (write through
//    io/atomic_file.h to get all-or-nothing files).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/coverage_map.h"
#include "io/output_plan.h"
#include "audit/audit.h"

namespace covmap::report {

// How curves become polylines and how the HTML picture is drawn. The defaults suit maps from a
// city to a region; every field is a tolerance or a size, none changes what is reported.
struct AuditRenderOptions {
  // Circle arcs of the recomputed diagram become polylines with at most this angle per segment
  // (degrees), so a small circle still looks round.
  double arc_step_degrees = 1.0;
  // ... and no segment farther than this from its arc, as a fraction of the diagram's extent (the
  // diagonal of its clip polygon's bounding box). 1e-5 of a 50 km map is 0.5 m, well below any
  // raster bin, so the polygons' areas match the true regions to about 1e-5.
  double arc_deviation = 1e-5;
  // Geographic output only: straight arcs are cut into pieces no longer than this fraction of the
  // extent, because a straight line of the projection plane is slightly curved in lon/lat.
  double geographic_line_step = 0.01;
  // sensors.geojson and diagram.geojson: coordinates with every bit (`--full-precision`) instead
  // of rounded to 1e-8 degrees or a millimetre, the precision any coverage map carries.
  bool full_precision = false;
  // sensors, shifts and diagram GeoJSON of a map in a projected CRS: coordinates in that CRS's
  // metres instead of WGS84 lon/lat, for outputs that carry the CRS (the GeoPackage keeps the
  // map's CRS; the .geojson files stay RFC 7946). No effect on other maps.
  bool crs_coordinates = false;
  // report.html: width of the map picture in CSS pixels; the height follows the map's aspect ratio.
  double html_width_px = 960.0;
  // report.html: space around the map's bounding box, as a fraction of its larger side.
  double html_margin = 0.03;
  // report.html: picture coordinates are integers on a grid of this many pixels (0.1 px: finer
  // than any screen shows at the nominal size, still sharp when zoomed in 10 times).
  double html_grid_px = 0.1;
  // report.html: polylines are simplified (Douglas-Peucker) so that no dropped vertex lies farther
  // than this from the drawn line, in pixels. This is what keeps a map of 10^4 raster cells small.
  double html_simplify_px = 0.25;
  // report.html: lon/lat of the cursor and the basemap's tiles are interpolated (bilinearly) on a
  // grid of this many cells a side over the map's frame; 32 keeps the error of a local projection
  // over a 500 km region well below a metre.
  int html_lonlat_grid = 32;
  // report.html, geographic maps only: a slippy-map tile URL ("https://tile.example/{z}/{x}/{y}.png")
  // drawn under the map when the reader switches the basemap on (`covmap audit --basemap`). Empty:
  // no basemap, and the page names no URL at all (it works offline and tells nobody it was opened).
  std::string basemap_url;

  // True if every field is usable; otherwise false, with the reason in *why if why is not null.
  bool is_valid(std::string* why = nullptr) const;
};

struct AuditReportContext {
  const audit::AuditResult& result;
  const io::CoverageMap& map;
  std::string map_file;                // as the user named it
  std::string sensors_file;            // empty: no --sensors
  std::optional<double> alpha;         // --alpha, the path-loss exponent, if given
  std::string command_line;            // for the record; written as is (escaped in HTML)
  // The options the audit ran with, for the "thresholds" of the reports; null: written as null.
  const audit::AuditOptions* options = nullptr;
  AuditRenderOptions render{};
};

// How the GIS layers of the report (sensors, shifts, diagram) are written (`covmap audit --format`):
// three RFC 7946 GeoJSON files (WGS84 lon/lat, or the plane of a map without a CRS), or one
// GeoPackage, audit.gpkg, with the three as tables in the map's own CRS (EPSG:4326 for a lon/lat
// map, none for a planar one).
enum class GisFormat { kGeoJson, kGeoPackage };
std::string_view gis_format_name(GisFormat format);                    // "geojson", "gpkg"
std::optional<GisFormat> gis_format_from_name(std::string_view name);  // nullopt if unknown

// The files of an audit's report folder, in the order they are rendered: report.json, report.html,
// then the GIS layers of `format`.
std::vector<std::string> audit_report_file_names(GisFormat format);
// Every file of the folder, each written into `folder` as it is rendered (io/output_plan.h's
// ReportFolderWriter, which the caller commits: all or nothing). The diagram layer, by far the
// largest, is rendered on a second thread beside the others. `progress`, if set, hears the name of
// each file before it is rendered. Throws std::runtime_error if GDAL cannot make the GeoPackage,
// io::OutputError if a file cannot be written.
void write_audit_reports(const AuditReportContext& context, GisFormat format, io::ReportFolderWriter& folder,
                         const std::function<void(const std::string& file)>& progress = {});

void write_audit_json(const AuditReportContext& context, std::ostream& out);       // report.json
void write_audit_html(const AuditReportContext& context, std::ostream& out);       // report.html
void write_sensors_geojson(const AuditReportContext& context, std::ostream& out);  // sensors.geojson
void write_shifts_geojson(const AuditReportContext& context, std::ostream& out);   // shifts.geojson
void write_diagram_geojson(const AuditReportContext& context, std::ostream& out);  // diagram.geojson

// How the audited sensors came out, as report.json, report.html and `covmap audit`'s summary line
// count them. Every sensor has exactly one verdict, so the counts by verdict add up to `sensors`.
struct AuditVerdictCounts {
  std::size_t sensors = 0;   // all entries of AuditResult::sensors: map sensors, then reported-only
  std::size_t in_map = 0;    // with a cell in the map
  std::size_t reported = 0;  // with reported values
  // by_verdict[i]: the sensors whose verdict is audit::kAllSensorVerdicts[i].
  std::array<std::size_t, std::size(audit::kAllSensorVerdicts)> by_verdict{};

  std::size_t of(audit::SensorVerdict verdict) const;
};
// Throws std::logic_error for a verdict missing from audit::kAllSensorVerdicts (a programming
// error: such a sensor would otherwise go uncounted).
AuditVerdictCounts count_verdicts(std::span<const audit::SensorAudit> sensors);
// The counts as report.json's "summary" object, as compact JSON text.
std::string verdict_counts_json(const AuditVerdictCounts& counts);

// A verdict in plain words, the same in the summary line, the HTML cards, legend and table:
// "consistent", "inconsistent", "undetermined (not judged)", "reported but not in the map", "in
// the map but not reported". Each sensor's reason says why in its own case.
std::string_view verdict_words(audit::SensorVerdict verdict);
// Every verdict with its count, in the order of audit::kAllSensorVerdicts, zero counts included, for
// people: "0 in the map but not reported, 47 consistent, 5 inconsistent, 6 undetermined (not
// judged), 0 reported but not in the map".
std::string verdict_counts_text(const AuditVerdictCounts& counts);

// The order in which sensors need a planner's attention, worst first: indices into
// `sensors`. By verdict: inconsistent, model misfit, reported but not in the map, in the map but
// not reported, undetermined, consistent; within a verdict by χ² (largest first, none last), then
// by position error (largest first, only where it was measured), then by id. report.html's list
// and its table's default order follow it.
std::vector<std::size_t> sensors_by_severity(std::span<const audit::SensorAudit> sensors);
// The verdicts a planner should look at: every one but consistent.
bool needs_attention(audit::SensorVerdict verdict);
// What a verdict rests on, for people: "the fit of its cell's boundaries", "its cell in the map",
// "the cell it would serve", "the model fit around it"; empty for VerdictBasis::kNone.
std::string_view basis_words(audit::VerdictBasis basis);

// The model fit in one sentence for people; empty when it was not measured. When the
// map does not follow the model it starts "The map does not follow the path-loss model", and every
// report puts it first.
std::string model_fit_text(const audit::AuditResult& result);
// The path-loss exponent the map and the reported powers imply, in one sentence, when the given
// alpha disagrees with it (it is then said first, as every dB figure depends on it); else empty.
std::string alpha_warning_text(const audit::AuditResult& result, std::optional<double> given_alpha);
// The estimate for people: "of 3.52 ± 0.06" (a narrow interval), "between 2.45 and 4.90", "of at
// least 2.45 ± 0.20" (no upper end).
std::string alpha_text(const audit::AlphaEstimate& estimate);
// The reception limit in one sentence; empty when the map has none.
std::string reception_text(const audit::AuditResult& result);

// Every repair the cleaning made: merged junctions, closed gaps, resolved overlaps, dropped short
// chains and snapped nodes.
std::size_t cleaning_repairs(const cleaning::CleaningReport& report);

}  // namespace covmap::report
