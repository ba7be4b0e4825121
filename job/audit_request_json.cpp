#include "job/audit_request_json.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace covmap::job {
namespace {

using Json = nlohmann::json;

constexpr const char* kRequestFormat = "covmap.audit-request/1";

[[noreturn]] void bad(AuditOption option, const std::string& message) { throw OptionsError(std::string(option_name(option)), message); }

// A JSON value printed for a message: short, so that a huge or deep value is not echoed whole.
std::string excerpt(const Json& v) {
  std::string text = v.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

bool boolean(const Json& v, AuditOption option) {
  if (!v.is_boolean()) bad(option, "must be true or false (got " + excerpt(v) + ")");
  return v.get<bool>();
}

std::string text(const Json& v, AuditOption option) {
  if (!v.is_string()) bad(option, "must be a string (got " + excerpt(v) + ")");
  std::string s = v.get<std::string>();
  if (std::string why = value_problem(option, s); !why.empty()) bad(option, why);
  return s;
}

// A number judged by the option's rule on its JSON text, so "2.5" for a band is refused as typed.
double number(const Json& v, AuditOption option) {
  if (!v.is_number()) bad(option, "must be a number (got " + excerpt(v) + ")");
  if (std::string why = value_problem(option, v.dump()); !why.empty()) bad(option, why);
  return v.get<double>();
}

std::string known_options() {
  std::string names;
  for (const AuditOption o : kServiceOptions) names += (names.empty() ? "" : ", ") + std::string(option_name(o));
  return names;
}

bool is_service_option(AuditOption option) {
  for (const AuditOption o : kServiceOptions)
    if (o == option) return true;
  return false;
}

void read_member(AuditRequest& r, AuditOption option, const Json& v) {
  switch (option) {
    case AuditOption::kAlpha: r.settings.alpha = number(v, option); return;
    case AuditOption::kSnap: r.settings.snap = number(v, option); return;
    case AuditOption::kThreads: r.settings.threads = static_cast<int>(number(v, option)); return;
    case AuditOption::kBand: r.inputs.band = static_cast<int>(number(v, option)); return;
    case AuditOption::kSensorProperty: r.inputs.sensor_property = text(v, option); return;
    case AuditOption::kLayer: r.inputs.layer = text(v, option); return;
    case AuditOption::kSensorLayer: r.inputs.sensor_layer = text(v, option); return;
    case AuditOption::kSensorCrs: r.inputs.sensor_crs = text(v, option); return;
    case AuditOption::kPlanar: r.inputs.planar = boolean(v, option); return;
    case AuditOption::kForce: r.settings.force = boolean(v, option); return;
    case AuditOption::kFullPrecision: r.outputs.full_precision = boolean(v, option); return;
    case AuditOption::kBasemap: r.outputs.basemap_url = text(v, option); return;
    case AuditOption::kFormat: r.outputs.format = *report::gis_format_from_name(text(v, option)); return;
  }
}

Json options_object(const AuditRequest& r) {
  Json o = {{"planar", r.inputs.planar},           {"full_precision", r.outputs.full_precision},
            {"force", r.settings.force},           {"sensor_property", r.inputs.sensor_property},
            {"layer", r.inputs.layer},             {"sensor_crs", r.inputs.sensor_crs},
            {"sensor_layer", r.inputs.sensor_layer}, {"basemap", r.outputs.basemap_url},
            {"snap", r.settings.snap},             {"band", r.inputs.band},
            {"threads", r.settings.threads},       {"format", report::gis_format_name(r.outputs.format)}};
  if (r.settings.alpha) o["alpha"] = *r.settings.alpha;
  return o;
}

}  // namespace

OptionsError::OptionsError(std::string m, std::string why)
    : std::invalid_argument(m.empty() ? why : m + ": " + why), member(std::move(m)), message(std::move(why)) {}

void read_options_json(std::string_view text_in, AuditRequest& request) {
  if (text_in.find_first_not_of(" \t\r\n") == std::string_view::npos) return;
  const Json j = Json::parse(text_in, nullptr, false);
  if (j.is_discarded()) throw OptionsError("", "is not valid JSON");
  if (!j.is_object()) throw OptionsError("", "must be a JSON object of audit options");
  for (const auto& [name, value] : j.items()) {
    const std::optional<AuditOption> option = option_from_name(name);
    if (!option || !is_service_option(*option))
      throw OptionsError(name.size() > 60 ? name.substr(0, 57) + "..." : name, "unknown option; known: " + known_options());
    read_member(request, *option, value);
  }
}

std::string request_json(const AuditRequest& r) {
  Json j = {{"format", kRequestFormat},
            {"map", r.inputs.map.string()},
            {"sensors", r.inputs.sensors.string()},
            {"raster_table", r.inputs.raster_table.string()},
            {"output", r.outputs.folder.string()},
            {"command_line", r.command_line},
            {"options", options_object(r)}};
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

AuditRequest request_from_json(std::string_view text_in) {
  const Json j = Json::parse(text_in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("format", "") != kRequestFormat)
    throw OptionsError("", std::string("is not a ") + kRequestFormat + " request");
  AuditRequest r;
  const auto path = [&](const char* name) {
    if (!j.contains(name) || !j[name].is_string()) throw OptionsError(name, "must be a string");
    return std::filesystem::path(j[name].get<std::string>());
  };
  r.inputs.map = path("map");
  r.inputs.sensors = path("sensors");
  r.inputs.raster_table = path("raster_table");
  r.outputs.folder = path("output");
  if (!j.contains("command_line") || !j["command_line"].is_string()) throw OptionsError("command_line", "must be a string");
  r.command_line = j["command_line"].get<std::string>();
  if (!j.contains("options") || !j["options"].is_object()) throw OptionsError("options", "must be an object");
  for (const auto& [name, value] : j["options"].items()) {
    const std::optional<AuditOption> option = option_from_name(name);
    if (!option) throw OptionsError(name, "unknown option");
    read_member(r, *option, value);
  }
  return r;
}

}  // namespace covmap::job
