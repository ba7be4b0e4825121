// covmap::io reported sensors: the sensors an operator says serve a coverage map (`covmap audit
// --sensors`), to be compared with what the map itself implies.
//
// Accepted (docs/FORMATS.md, "Coverage maps and reported sensors", has the full grammar):
//   JSON     {"format":"covmap.sites/1","sites":[{"id":"a","x":0,"y":0,"weight":1}, ...]}, where
//            each entry may give lon/lat instead of x/y, and tx_power_dbm instead of or besides
//            weight, and optionally name, position_sigma_m and power_sigma_db (null = not given).
//   CSV      a header naming id; x and y, or lon and lat; weight and/or tx_power_dbm; optionally
//            name, position_sigma_m and power_sigma_db (any order, case-insensitive, other columns
//            ignored); then one sensor per row. An empty optional field is "not given". Blank lines
//            and lines starting with # are skipped; fields may be double-quoted.
//   GeoJSON  a FeatureCollection of Point features; the id is properties.id, else properties.sensor,
//            else the feature's "id" member; name, weight, tx_power_dbm and the sigmas are properties.
//            Positions are [lon, lat] unless options.planar ([x, y]); crs as in io/geojson_crs.h.
// Chosen by extension (.csv, .geojson, .json), otherwise by content: JSON with a "format" member is
// covmap.sites/1, JSON with a "type" is GeoJSON, anything else CSV.
// A well-formed GeoJSON file is read in one pass over its text, anything else through a JSON
// document that also words every problem (io/reported_sensors_parsers.h); the results are the same.
//
// Strength: every sensor needs a weight or a tx_power_dbm. A weight as read is kept. A sensor with
// only a power gets weight = weight_from_power(power, alpha), which needs options.alpha (a power
// in dB and a weight are related only through the path-loss exponent). A power is never derived
// from a weight: weights are defined only up to a common factor, so such a power would be
// meaningless.
//
// Positions: lon/lat input is placed with options.frame (the map's), which must then be set. x/y
// input is in the CRS of options.xy_frame when one is set (`--sensor-crs`, or a GeoJSON "crs"
// resolved by options.resolve_crs) and goes through WGS84 into the map's plane, which needs a map
// with a frame; without one, x/y are taken to be the map's own plane: as they are for a planar map
// or a map in a projected CRS, refused against a lon/lat map (the sensors would silently land in
// the wrong place). A sensor that gives both pairs (vendor exports do) is placed with x/y when their
// CRS is declared or the map is planar, with lon/lat otherwise, and options.notes says so once per
// file.
//
// Names: a sensor's human name ("Zollikofen") is optional text kept as read in ReportedSensor::name
// (empty when absent, null or an empty field); names need not be unique and are never used to
// match sensors (ids are). In JSON it must be a string: a number or anything else is a problem.
//
// Guaranteed on success: at least one sensor; ids unique and non-empty; positions finite, lon/lat
// in range, and no two sensors at the same position as read; weight set, finite and > 0; powers
// finite; sigmas finite and > 0. Sensors keep file order.
//
// Rejected with one InputError listing every problem, each naming the line (CSV) or JSON path
// ("sites[3]", "features[3]") and the sensor id: unreadable file, invalid JSON, wrong format tag,
// bad header, missing or malformed fields (a JSON name that is not a string, text that is not
// UTF-8), values out of range, "tx_power_dbm needs --alpha",
// lon/lat without a projection, x/y against a lon/lat map without their CRS, x/y in a declared CRS
// against a map without one, duplicate ids and duplicate positions
// (naming both sensors). Invalid options (alpha not finite and > 0, or planar together with a
// projection) are a caller's mistake and throw std::invalid_argument.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/map_frame.h"
#include "core/diagram.h"
#include "core/reported_sensor.h"

namespace covmap::io {

struct ReportedSensorOptions {
  // Path-loss exponent (`--alpha`): received power falls by 10 * alpha dB per decade of distance.
  // Needed only for sensors that give a power but no weight. Must be finite and > 0 when set.
  std::optional<double> alpha;
  // The map's frame (io/map_frame.h), for sensor files that are not in the map's plane. Null for a
  // planar map without a CRS.
  const MapFrame* frame = nullptr;
  // The CRS of the file's x/y positions (`--sensor-crs`; a GeoJSON file's positions are then [x, y]
  // in it, whatever "crs" it declares); null: the file's own declaration, if resolve_crs reads one,
  // else the map's plane.
  std::shared_ptr<const MapFrame> xy_frame;
  // Reads a GeoJSON sensor file's non-WGS84 "crs" declaration (as CoverageMapOptions::resolve_crs):
  // its positions are then x/y in that CRS.
  CrsResolver resolve_crs;
  // The map is planar (`--planar`): GeoJSON positions are [x, y]. Must not be set with a projection.
  bool planar = false;
  // Where the reader says which of two readings it chose, for people ("used lon/lat, as the map is
  // in lon/lat" when a sensor gives both x/y and lon/lat); null: not said.
  std::vector<std::string>* notes = nullptr;
};

enum class SensorsFormat { kDetect, kCsv, kSitesJson, kGeoJson };

std::vector<ReportedSensor> read_reported_sensors(const std::filesystem::path& path, const ReportedSensorOptions& options);

// Parses text already in memory; `file` is only used in error messages. kDetect looks at the
// content only.
std::vector<ReportedSensor> parse_reported_sensors(std::string_view text, const std::string& file,
                                                   const ReportedSensorOptions& options,
                                                   SensorsFormat format = SensorsFormat::kDetect);

// The weight of a sensor transmitting tx_power_dbm under path-loss exponent alpha:
// 10^(P / (10 alpha)). Why: received power P - 10 alpha log10(d) is largest for the sensor with
// the smallest d / 10^(P / (10 alpha)), which is the multiplicatively weighted distance |p - s| / w.
// Throws std::invalid_argument unless alpha is finite and > 0.
double weight_from_power(double tx_power_dbm, double alpha);
// The inverse: 10 alpha log10(weight). Throws std::invalid_argument unless alpha is finite and > 0
// and weight is finite and > 0.
double power_from_weight(double weight, double alpha);

}  // namespace covmap::io
