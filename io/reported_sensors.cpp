#include "io/reported_sensors.h"

#include <cctype>
#include <cmath>
#include <stdexcept>

#include "core/round_trip_numbers.h"
#include "io/input_error.h"
#include "io/input_limits.h"
#include "io/reported_sensors_parsers.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

void check_alpha(double alpha) {
  if (!std::isfinite(alpha) || !(alpha > 0)) {
    throw std::invalid_argument("path-loss exponent alpha must be finite and > 0 (got " + round_trip_number(alpha) + ")");
  }
}

void check_options(const ReportedSensorOptions& options) {
  if (options.alpha) check_alpha(*options.alpha);
  if (options.planar && options.frame) {
    throw std::invalid_argument("ReportedSensorOptions: planar and a projection are mutually exclusive");
  }
}

bool looks_like_json(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && text[first] == '{';
}

// kDetect with `json` set: the text is JSON (a .json file), and its content says which kind.
std::vector<ReportedSensor> parse(std::string_view text, const std::string& file, const ReportedSensorOptions& options,
                                  SensorsFormat format, bool json) {
  check_options(options);
  if (format == SensorsFormat::kDetect && !json && !looks_like_json(text)) format = SensorsFormat::kCsv;
  std::vector<InputProblem> file_problems;
  std::vector<detail::SensorDraft> drafts;
  std::shared_ptr<const MapFrame> declared;  // a GeoJSON file's own CRS
  if (format == SensorsFormat::kCsv) {
    drafts = detail::parse_sensors_csv(text, file);
  } else if (std::optional<std::vector<detail::SensorDraft>> fast =
                 format == SensorsFormat::kSitesJson
                     ? std::nullopt
                     : detail::parse_sensors_geojson_fast(text, options.planar, options.xy_frame != nullptr,
                                                          options.resolve_crs, declared, file_problems)) {
    drafts = std::move(*fast);  // a well-formed GeoJSON file, read in one pass
  } else {
    const detail::Json root = detail::parse_json(text, file);
    // covmap.sites/1 carries a "format" member; GeoJSON carries a "type" instead.
    const bool geojson = format == SensorsFormat::kGeoJson ||
                         (format == SensorsFormat::kDetect && root.is_object() && !root.contains("format") &&
                          root.contains("type"));
    drafts = geojson ? detail::parse_sensors_geojson(root, file, options.planar, options.xy_frame != nullptr, options.resolve_crs,
                                                   declared, file_problems)
                     : detail::parse_sensors_sites_json(root, file);
  }
  const MapFrame* xy_frame = options.xy_frame ? options.xy_frame.get() : declared.get();
  return detail::finish_sensors(std::move(drafts), file, options, xy_frame, std::move(file_problems));
}

}  // namespace

double weight_from_power(double tx_power_dbm, double alpha) {
  check_alpha(alpha);
  return std::pow(10.0, tx_power_dbm / (10.0 * alpha));
}

double power_from_weight(double weight, double alpha) {
  check_alpha(alpha);
  if (!std::isfinite(weight) || !(weight > 0)) {
    throw std::invalid_argument("weight must be finite and > 0 (got " + round_trip_number(weight) + ")");
  }
  return 10.0 * alpha * std::log10(weight);
}

namespace {

std::vector<ReportedSensor> within_limit(std::vector<ReportedSensor> sensors, const std::string& file) {
  if (sensors.size() > kMaxReportedSensors)
    throw InputError(file, 0, "", std::to_string(sensors.size()) + " sensors; covmap audits at most " +
                                      std::to_string(kMaxReportedSensors) + " (docs/RELIABILITY.md)");
  return sensors;
}

}  // namespace

std::vector<ReportedSensor> parse_reported_sensors(std::string_view text, const std::string& file,
                                                   const ReportedSensorOptions& options, SensorsFormat format) {
  return within_limit(parse(text, file, options, format, false), file);
}

std::vector<ReportedSensor> read_reported_sensors(const std::filesystem::path& path, const ReportedSensorOptions& options) {
  check_options(options);  // before touching the file: a bad option is not the file's fault
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const SensorsFormat format = ext == ".csv"       ? SensorsFormat::kCsv
                               : ext == ".geojson" ? SensorsFormat::kGeoJson
                                                   : SensorsFormat::kDetect;
  return within_limit(parse(detail::read_text_file(path), path.string(), options, format, ext == ".json"), path.string());
}

}  // namespace covmap::io
