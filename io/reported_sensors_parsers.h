// The three syntaxes behind read_reported_sensors (internal to io/). Each turns its file into
// drafts holding the values as read plus the problems found on the way; finish_sensors then applies
// the same rules and wording to all of them.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/input_error.h"
#include "io/json_fields.h"
#include "io/reported_sensors.h"

namespace covmap::io::detail {

struct SensorDraft {
  ReportedSensor sensor;  // id, strengths, sigmas and origin as read; position not yet set
  std::optional<Point> xy;  // a planar position as read
  std::optional<LonLat> lon_lat;     // a geographic position as read
  int line = 0;                      // line in a CSV file; 0 for JSON
  std::vector<std::string> problems;  // what is wrong so far, in the order found
  bool usable() const { return problems.empty(); }
};

// How a problem names the sensor: "sensor 'b'" in CSV (the line says where), "features[3]
// (sensor 'b')" in JSON.
std::string sensor_label(const SensorDraft& draft);

// Each parser throws InputError for problems with the file as a whole (syntax, header, format
// tag) and leaves per-sensor problems in the drafts. `file_problems` receives problems of the file
// that do not stop the reading (the GeoJSON crs checks).
std::vector<SensorDraft> parse_sensors_csv(std::string_view text, const std::string& file);
std::vector<SensorDraft> parse_sensors_sites_json(const Json& root, const std::string& file);
// Positions are x/y with `planar`, with `xy_crs` (the caller names their CRS: --sensor-crs) or when
// the file declares a non-WGS84 CRS at its top that `resolve` reads (its frame then goes to
// `declared`); lon/lat otherwise.
std::vector<SensorDraft> parse_sensors_geojson(const Json& root, const std::string& file, bool planar, bool xy_crs,
                                               const CrsResolver& resolve, std::shared_ptr<const MapFrame>& declared,
                                               std::vector<InputProblem>& file_problems);

// The same drafts as parse_sensors_geojson for a well-formed GeoJSON text, read in one pass
// (reported_sensors_fast.cpp; the scanner of io/json_scan.h); nullopt whenever anything is out of
// the ordinary, including any problem the reference would report in a draft or the file, and for a
// text with a "format" member (covmap.sites/1 when the format is detected). `declared` and
// `file_problems` are set only when drafts are returned. The reference then reads the text and
// words every problem, so every message is the reference's (tests/io/reported_sensors_fast_test.cpp).
std::optional<std::vector<SensorDraft>> parse_sensors_geojson_fast(std::string_view text, bool planar, bool xy_crs,
                                                                   const CrsResolver& resolve,
                                                                   std::shared_ptr<const MapFrame>& declared,
                                                                   std::vector<InputProblem>& file_problems);

// Value checks, strengths, projection, unique ids and positions; then the sensors, or one
// InputError listing `file_problems` followed by every sensor's problems in file order.
// `xy_frame`: the CRS of the drafts' x/y (options.xy_frame or the file's declaration); null: the
// map's plane.
std::vector<ReportedSensor> finish_sensors(std::vector<SensorDraft> drafts, const std::string& file,
                                           const ReportedSensorOptions& options, const MapFrame* xy_frame,
                                           std::vector<InputProblem> file_problems);

}  // namespace covmap::io::detail
