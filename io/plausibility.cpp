#include "io/plausibility.h"

#include <algorithm>
#include <cmath>

#include "core/box.h"
#include "core/readable_numbers.h"

namespace covmap::io {
namespace {

Box map_box(const CoverageMap& map) {
  Box box;
  for (const MapCell& cell : map.cells)
    for (const MapPolygon& polygon : cell.polygons)
      for (const Point& p : polygon.outer) box.add(p);
  return box;
}

}  // namespace

std::optional<std::string> lon_lat_looking(const CoverageMap& map) {
  if (map.frame && map.frame->kind() == FrameKind::kLocalProjection) return std::nullopt;  // read as degrees
  const Box box = map_box(map);
  if (box.empty() || box.xmin < -180 || box.xmax > 180 || box.ymin < -90 || box.ymax > 90) return std::nullopt;
  if (std::max(box.width(), box.height()) >= kLonLatLookingSpan) return std::nullopt;
  return "the map's coordinates all lie within longitude/latitude ranges (x " + fixed(box.xmin, 4) + " to " +
         fixed(box.xmax, 4) + ", y " + fixed(box.ymin, 4) + " to " + fixed(box.ymax, 4) +
         "), but " + (map.frame ? "its CRS, " + map.frame->description() + "," : std::string("--planar")) +
         " reads them as metres: a map " + metres(box.width()) + " wide; " +
         (map.frame ? "if they are degrees, declare the CRS they are in (e.g. ogr2ogr -a_srs EPSG:4326)"
                    : "drop --planar if they are degrees");
}

std::optional<std::string> sensors_far_outside(const CoverageMap& map, const std::vector<ReportedSensor>& sensors) {
  const Box box = map_box(map);
  if (box.empty()) return std::nullopt;
  const double limit = kFarOutsideDiagonals * box.diagonal();
  std::size_t count = 0;
  double farthest = 0.0;
  std::string farthest_id;
  for (const ReportedSensor& s : sensors) {
    const double d = box.distance_to(s.position);
    if (!(d > limit)) continue;
    ++count;
    if (d > farthest) {
      farthest = d;
      farthest_id = s.id;
    }
  }
  if (count == 0) return std::nullopt;
  return plural(count, "reported sensor") + (count == 1 ? " lies" : " lie") + " farther outside the map than its own size (" +
         metres(box.diagonal()) + " corner to corner); the farthest, '" + farthest_id + "', is " +
         metres(farthest) + " away: wrong positions, a wrong unit, or the wrong map?";
}

}  // namespace covmap::io
