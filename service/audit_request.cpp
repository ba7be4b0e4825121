#include "service/audit_request.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

#include "report/audit_report.h"
#include "service/api_error.h"

namespace covmap::service {
namespace {

using Json = nlohmann::json;

constexpr const char* kKnown =
    "alpha, planar, full_precision, force, sensor_property, layer, sensor_crs, sensor_layer, basemap, snap, band, format";

[[noreturn]] void bad(const std::string& member, const std::string& message) {
  throw ApiError(ErrorCode::kBadInput, message, "options." + member);
}

bool boolean(const Json& v, const std::string& name) {
  if (!v.is_boolean()) bad(name, "must be true or false (got " + v.dump() + ")");
  return v.get<bool>();
}

std::string text(const Json& v, const std::string& name) {
  if (!v.is_string()) bad(name, "must be a string (got " + v.dump() + ")");
  return v.get<std::string>();
}

double number(const Json& v, const std::string& name) {
  if (!v.is_number()) bad(name, "must be a number (got " + v.dump() + ")");
  const double x = v.get<double>();
  if (!std::isfinite(x)) bad(name, "must be finite");
  return x;
}

void read_member(AuditRequest& r, const std::string& name, const Json& v) {
  if (name == "alpha") {
    const double a = number(v, name);
    if (!(a > 0)) bad(name, "must be > 0 (the path-loss exponent)");
    r.alpha = a;
  } else if (name == "planar") {
    r.planar = boolean(v, name);
  } else if (name == "full_precision") {
    r.full_precision = boolean(v, name);
  } else if (name == "force") {
    r.force = boolean(v, name);
  } else if (name == "sensor_property") {
    r.sensor_property = text(v, name);
    if (r.sensor_property.empty()) bad(name, "must not be empty");
  } else if (name == "layer") {
    r.layer = text(v, name);
  } else if (name == "sensor_crs") {
    r.sensor_crs = text(v, name);
  } else if (name == "sensor_layer") {
    r.sensor_layer = text(v, name);
  } else if (name == "basemap") {
    r.basemap = text(v, name);
  } else if (name == "snap") {
    r.snap = number(v, name);
    if (r.snap < 0) bad(name, "must be >= 0");
  } else if (name == "band") {
    if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 65535) bad(name, "must be an integer in 1-65535");
    r.band = v.get<int>();
  } else if (name == "format") {
    const std::string f = text(v, name);
    const auto format = report::gis_format_from_name(f);
    if (!format) bad(name, "must be \"geojson\" or \"gpkg\" (got \"" + f + "\")");
    r.geopackage = *format == report::GisFormat::kGeoPackage;
  } else {
    bad(name, "unknown option; known: " + std::string(kKnown));
  }
}

// A number as text that reads back to the same double, for the job's command line.
std::string exact(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

}  // namespace

AuditRequest parse_audit_request(std::string_view options_json) {
  AuditRequest r;
  if (options_json.find_first_not_of(" \t\r\n") == std::string_view::npos) return r;
  const Json j = Json::parse(options_json, nullptr, false);
  if (j.is_discarded()) throw ApiError(ErrorCode::kBadInput, "is not valid JSON", "options");
  if (!j.is_object()) throw ApiError(ErrorCode::kBadInput, "must be a JSON object of audit options", "options");
  for (const auto& [name, value] : j.items()) read_member(r, name, value);
  return r;
}

std::vector<std::string> audit_arguments(const AuditRequest& r, const std::filesystem::path& map,
                                         const std::filesystem::path& sensors, const std::filesystem::path& output_dir) {
  std::vector<std::string> a = {"audit", map.string(), "-o", output_dir.string(), "--sensor-property", r.sensor_property};
  if (!sensors.empty()) a.insert(a.end(), {"--sensors", sensors.string()});
  if (r.alpha) a.insert(a.end(), {"--alpha", exact(*r.alpha)});
  if (r.planar) a.push_back("--planar");
  if (r.full_precision) a.push_back("--full-precision");
  if (r.force) a.push_back("--force");
  if (!r.layer.empty()) a.insert(a.end(), {"--layer", r.layer});
  if (!r.sensor_crs.empty()) a.insert(a.end(), {"--sensor-crs", r.sensor_crs});
  if (!r.sensor_layer.empty()) a.insert(a.end(), {"--sensor-layer", r.sensor_layer});
  if (!r.basemap.empty()) a.insert(a.end(), {"--basemap", r.basemap});
  if (r.snap > 0) a.insert(a.end(), {"--snap", exact(r.snap)});
  if (r.band != 1) a.insert(a.end(), {"--band", std::to_string(r.band)});
  if (r.geopackage) a.insert(a.end(), {"--format", "gpkg"});
  return a;
}

std::vector<std::string> report_files(const AuditRequest& request) {
  return report::audit_report_file_names(request.geopackage ? report::GisFormat::kGeoPackage : report::GisFormat::kGeoJson);
}

}  // namespace covmap::service
