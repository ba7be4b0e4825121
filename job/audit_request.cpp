#include "job/audit_request.h"


#include "audit/audit.h"
#include "core/round_trip_numbers.h"
#include "core/typed_numbers.h"

namespace covmap::job {
namespace {

constexpr std::array<std::string_view, kAllAuditOptions.size()> kNames = {
    "alpha", "snap",     "threads",   "band",           "sensor_property", "layer",  "sensor_layer",
    "sensor_crs", "planar", "force", "full_precision", "basemap",         "format"};

std::string basemap_problem(const std::string& url) {
  report::AuditRenderOptions render;
  render.basemap_url = url;
  std::string why;
  if (!render.is_valid(&why)) return why.substr(why.find("must"));
  if (!url.starts_with("https://") && !url.starts_with("http://") && !url.starts_with("file://"))
    return "give an http://, https:// or file:// URL";
  return "";
}

}  // namespace

std::string_view option_name(AuditOption option) { return kNames[static_cast<std::size_t>(option)]; }

std::optional<AuditOption> option_from_name(std::string_view name) {
  for (const AuditOption o : kAllAuditOptions)
    if (option_name(o) == name) return o;
  return std::nullopt;
}

std::string value_problem(AuditOption option, std::string_view text) {
  const std::string typed(text);
  switch (option) {
    case AuditOption::kAlpha: return positive_number_problem(text);
    case AuditOption::kSnap: return non_negative_number_problem(text);
    case AuditOption::kThreads: return whole_number_problem(text, 1, 64);
    case AuditOption::kBand: return whole_number_problem(text, 1, 65535);
    case AuditOption::kSensorProperty: return text.empty() ? "must not be empty" : "";
    case AuditOption::kBasemap: return text.empty() ? "" : basemap_problem(typed);
    case AuditOption::kFormat:
      return report::gis_format_from_name(text) ? "" : "must be \"geojson\" or \"gpkg\" (got \"" + typed + "\")";
    case AuditOption::kLayer:
    case AuditOption::kSensorLayer:
    case AuditOption::kSensorCrs:
    case AuditOption::kPlanar:
    case AuditOption::kForce:
    case AuditOption::kFullPrecision: return "";
  }
  return "";
}

std::vector<RequestProblem> request_problems(const AuditRequest& r) {
  std::vector<RequestProblem> found;
  const auto check = [&](AuditOption option, const std::string& text) {
    if (std::string why = value_problem(option, text); !why.empty()) found.push_back({option, std::move(why)});
  };
  if (r.settings.alpha) check(AuditOption::kAlpha, round_trip_number(*r.settings.alpha));
  check(AuditOption::kSnap, round_trip_number(r.settings.snap));
  check(AuditOption::kThreads, std::to_string(r.settings.threads));
  check(AuditOption::kBand, std::to_string(r.inputs.band));
  check(AuditOption::kSensorProperty, r.inputs.sensor_property);
  check(AuditOption::kBasemap, r.outputs.basemap_url);
  // A tile layer is drawn under lon/lat maps only: a planar map has no place on the globe.
  if (!r.outputs.basemap_url.empty() && r.inputs.planar)
    found.push_back({AuditOption::kBasemap, "cannot be used with planar data (they have no place on the globe)"});
  return found;
}

InvalidAuditRequest::InvalidAuditRequest(RequestProblem p)
    : std::invalid_argument(std::string(option_name(p.option)) + ": " + p.message), problem(std::move(p)) {}

void validate(const AuditRequest& request) {
  const std::vector<RequestProblem> problems = request_problems(request);
  if (!problems.empty()) throw InvalidAuditRequest(problems.front());
}

gis::MapReadOptions map_read_options(const AuditRequest& r) {
  gis::MapReadOptions o;
  o.map.sensor_property = r.inputs.sensor_property;
  o.map.planar = r.inputs.planar;
  o.map.max_sensors = audit::kMaxSensors;
  o.layer = r.inputs.layer;
  o.band = r.inputs.band;
  o.raster_table = r.inputs.raster_table;
  return o;
}

gis::SensorReadOptions sensor_read_options(const AuditRequest& r) {
  gis::SensorReadOptions o;
  o.sensors.alpha = r.settings.alpha;
  o.sensors.planar = r.inputs.planar;
  o.sensor_crs = r.inputs.sensor_crs;
  o.layer = r.inputs.sensor_layer;
  return o;
}

}  // namespace covmap::job
