// The report folder as a whole: which files, rendered in order, the GIS layers as GeoJSON or as
// one GeoPackage (through gis/geopackage.h, which keeps the map's CRS).
#include <future>
#include <sstream>

#include "gis/geopackage.h"
#include "report/audit_report.h"

namespace covmap::report {
namespace {

constexpr const char* kGeoPackageFile = "audit.gpkg";

// A plane of metres with no place on the earth: what a planar map's coordinates are. Without it
// GeoPackage would file them under "undefined geographic", i.e. degrees.
constexpr const char* kPlanarCrs =
    "ENGCRS[\"covmap planar map (metres, no CRS)\",EDATUM[\"unknown\"],CS[Cartesian,2],"
    "AXIS[\"x\",east,ORDER[1],LENGTHUNIT[\"metre\",1]],AXIS[\"y\",north,ORDER[2],LENGTHUNIT[\"metre\",1]]]";

// The CRS the GeoPackage's coordinates are in: the map's projected CRS, WGS84 lon/lat for a map
// covmap projected itself, a plane of metres for a planar map.
std::string geopackage_crs(const io::CoverageMap& map) {
  if (!map.frame) return kPlanarCrs;
  if (map.frame->kind() == io::FrameKind::kProjectedCrs) return map.frame->crs_wkt();
  return "EPSG:4326";
}

using Writer = void (*)(const AuditReportContext&, std::ostream&);

std::string rendered(Writer write, const AuditReportContext& context) {
  std::ostringstream out;
  write(context, out);
  return std::move(out).str();  // the buffer itself, not a copy (a large diagram is tens of MB)
}

}  // namespace

std::string_view gis_format_name(GisFormat format) {
  switch (format) {
    case GisFormat::kGeoJson: return "geojson";
    case GisFormat::kGeoPackage: return "gpkg";
  }
  return "geojson";
}

std::optional<GisFormat> gis_format_from_name(std::string_view name) {
  for (const GisFormat f : {GisFormat::kGeoJson, GisFormat::kGeoPackage})
    if (gis_format_name(f) == name) return f;
  return std::nullopt;
}

std::vector<std::string> audit_report_file_names(GisFormat format) {
  switch (format) {
    case GisFormat::kGeoJson: return {"report.json", "report.html", "sensors.geojson", "shifts.geojson", "diagram.geojson"};
    case GisFormat::kGeoPackage: return {"report.json", "report.html", kGeoPackageFile};
  }
  return {};
}

void write_audit_reports(const AuditReportContext& context, GisFormat format, io::ReportFolderWriter& folder,
                         const std::function<void(const std::string& file)>& progress) {
  const auto say = [&](const std::string& file) {
    if (progress) progress(file);
  };
  const auto streamed = [&folder](const std::string& name, Writer write, const AuditReportContext& c) {
    folder.add(name, [write, &c](std::ostream& out) { write(c, out); });
  };
  // The layers of a GeoPackage are in the map's own CRS; GeoJSON is WGS84 (RFC 7946).
  AuditReportContext layer_context = context;
  layer_context.render.crs_coordinates = context.render.crs_coordinates || format == GisFormat::kGeoPackage;
  if (format == GisFormat::kGeoJson) {
    // Every file reads only the finished result. The diagram layer is by far the largest, the HTML
    // page next (its map drawn from the cells and diagrams): each takes about as long as all the
    // rest, so each is written on a thread of its own while the rest are.
    std::future<void> diagram = std::async(std::launch::async, [&] {
      streamed("diagram.geojson", write_diagram_geojson, layer_context);
    });
    std::future<void> html = std::async(std::launch::async, [&] { streamed("report.html", write_audit_html, context); });
    say("report.json");
    streamed("report.json", write_audit_json, context);
    say("sensors.geojson");
    streamed("sensors.geojson", write_sensors_geojson, layer_context);
    say("shifts.geojson");
    streamed("shifts.geojson", write_shifts_geojson, layer_context);
    say("report.html");
    html.get();
    say("diagram.geojson");
    diagram.get();
    return;
  }
  say("report.json");
  streamed("report.json", write_audit_json, context);
  say("report.html");
  streamed("report.html", write_audit_html, context);
  // GDAL makes the GeoPackage from the three layers as GeoJSON, in memory.
  say(kGeoPackageFile);
  const std::vector<gis::GeoJsonLayer> tables = {
      {"sensors", gis::LayerGeometry::kPoint, rendered(write_sensors_geojson, layer_context)},
      {"shifts", gis::LayerGeometry::kLineString, rendered(write_shifts_geojson, layer_context)},
      {"diagram", gis::LayerGeometry::kMultiPolygon, rendered(write_diagram_geojson, layer_context)}};
  folder.add(kGeoPackageFile, gis::geopackage_bytes(tables, geopackage_crs(context.map)));
}

}  // namespace covmap::report
