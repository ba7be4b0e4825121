#include "io/polygon_io.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <filesystem>

#include "io/input_error.h"
#include "io/json_fields.h"
#include "io/polygon_check.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

using detail::FieldError;
using detail::Json;

// The four numbers of "xmin,ymin,xmax,ymax", or nullopt if spec is not four numbers.
std::optional<std::array<double, 4>> rectangle_numbers(const std::string& spec) {
  std::array<double, 4> out{};
  std::size_t start = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t end = k < 3 ? spec.find(',', start) : spec.size();
    if (end == std::string::npos) return std::nullopt;
    std::string_view field = detail::trim(std::string_view(spec).substr(start, end - start));
    if (!field.empty() && field.front() == '+') field.remove_prefix(1);
    const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), out[k]);
    if (field.empty() || ec != std::errc() || ptr != field.data() + field.size()) return std::nullopt;
    start = end + 1;
  }
  return out;
}

std::vector<Point> rectangle(const std::array<double, 4>& v, const std::string& spec) {
  const auto [xmin, ymin, xmax, ymax] = v;
  const std::string item = "clip rectangle '" + spec + "'";
  for (const double c : v) {
    if (!std::isfinite(c)) throw InputError("", 0, item, "coordinates must be finite");
  }
  if (!(xmin < xmax) || !(ymin < ymax)) {
    throw InputError("", 0, item, "expected xmin,ymin,xmax,ymax with xmin < xmax and ymin < ymax");
  }
  return {{xmin, ymin}, {xmax, ymin}, {xmax, ymax}, {xmin, ymax}};
}

std::vector<Point> ring_from_json(const Json& positions, const std::string& path) {
  detail::expect_array(positions, path);
  std::vector<Point> ring;
  ring.reserve(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const std::string at = detail::element_path(path, i);
    const Json& p = positions[i];
    // GeoJSON positions may carry a third (altitude) value; a plane polygon needs the first two.
    if (!p.is_array() || p.size() < 2) throw FieldError(at, "must be an array [x, y] (got " + detail::describe(p) + ")");
    ring.push_back({detail::finite_number(p[0], detail::element_path(at, 0)),
                    detail::finite_number(p[1], detail::element_path(at, 1))});
  }
  return ring;
}

// The outer ring of a GeoJSON object, with the JSON path it came from.
std::pair<std::vector<Point>, std::string> geojson_ring(const Json& object, const std::string& path) {
  const Json& type = detail::member(object, "type", path);
  const std::string type_path = detail::member_path(path, "type");
  if (!type.is_string()) throw FieldError(type_path, "must be a string (got " + detail::describe(type) + ")");
  const auto& name = type.get_ref<const std::string&>();
  if (name == "Feature") {
    const std::string geometry_path = detail::member_path(path, "geometry");
    return geojson_ring(detail::member(object, "geometry", path), geometry_path);
  }
  if (name == "FeatureCollection") {
    const Json& features = detail::member(object, "features", path);
    const std::string features_path = detail::member_path(path, "features");
    detail::expect_array(features, features_path);
    if (features.size() != 1) {
      throw FieldError(features_path, "must hold exactly one Feature to be a clip polygon (got " +
                                          std::to_string(features.size()) + ")");
    }
    return geojson_ring(features[0], detail::element_path(features_path, 0));
  }
  if (name != "Polygon") throw FieldError(type_path, "expected \"Polygon\", \"Feature\" or \"FeatureCollection\" (got " + detail::describe(type) + ")");
  const std::string coordinates_path = detail::member_path(path, "coordinates");
  const Json& rings = detail::member(object, "coordinates", path);
  detail::expect_array(rings, coordinates_path);
  if (rings.empty()) throw FieldError(coordinates_path, "has no rings");
  if (rings.size() > 1) {
    throw FieldError(coordinates_path, "has " + std::to_string(rings.size() - 1) +
                                           " hole(s); clip polygons with holes are not supported");
  }
  const std::string ring_path = detail::element_path(coordinates_path, 0);
  return {ring_from_json(rings[0], ring_path), ring_path};
}

}  // namespace

std::vector<Point> make_clip_polygon(std::vector<Point> ring, const std::string& file, const std::string& item) {
  // GeoJSON repeats the first vertex at the end; hand-written files often repeat a vertex. Neither
  // changes the polygon, so drop them here rather than reject them.
  std::vector<Point> clean;
  clean.reserve(ring.size());
  for (const Point& p : ring) {
    if (clean.empty() || clean.back().x != p.x || clean.back().y != p.y) clean.push_back(p);
  }
  while (clean.size() > 1 && clean.front().x == clean.back().x && clean.front().y == clean.back().y) clean.pop_back();
  if (const auto defect = polygon_defect(clean)) throw InputError(file, 0, item, *defect);
  if (ring_orientation(clean) < 0) std::reverse(clean.begin(), clean.end());
  return clean;
}

std::vector<Point> parse_polygon_json(const std::string& text, const std::string& file) {
  const Json root = detail::parse_json(text, file);
  try {
    if (!root.is_object()) throw FieldError("", "top level must be a JSON object (got " + detail::describe(root) + ")");
    if (root.contains("format")) {
      detail::check_format_tag(root, "covmap.polygon/1", file);
      return make_clip_polygon(ring_from_json(detail::member(root, "points", ""), "points"), file, "points");
    }
    if (!root.contains("type")) {
      throw FieldError("", "expected {\"format\":\"covmap.polygon/1\", ...} or a GeoJSON Polygon or Feature");
    }
    auto [ring, path] = geojson_ring(root, "");
    return make_clip_polygon(std::move(ring), file, path);
  } catch (const FieldError& e) {
    throw InputError(file, 0, e.path, e.message);
  }
}

std::vector<Point> parse_clip(const std::string& spec) {
  std::error_code ec;
  const bool is_file = std::filesystem::exists(spec, ec);
  if (!is_file) {
    if (const auto numbers = rectangle_numbers(spec)) return rectangle(*numbers, spec);
    // Looks like an attempt at a rectangle (only number characters and commas): say so, rather
    // than "no such file".
    if (!spec.empty() && spec.find_first_not_of("0123456789+-.eE, \t") == std::string::npos) {
      throw InputError("", 0, "clip rectangle '" + spec + "'", "expected four numbers xmin,ymin,xmax,ymax");
    }
  }
  return parse_polygon_json(detail::read_text_file(spec), spec);
}

}  // namespace covmap::io
