#include "tools/mapgen/map_projection.h"

#include <GeographicLib/TransverseMercator.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace covmap::mapgen {
namespace {

const GeographicLib::TransverseMercator& wgs84_tm() {
  // Scale 1 on the central meridian: lengths near the centre are true lengths.
  static const GeographicLib::TransverseMercator tm(GeographicLib::Constants::WGS84_a(),
                                                    GeographicLib::Constants::WGS84_f(), 1.0);
  return tm;
}

}  // namespace

MapProjection MapProjection::about(double lon0, double lat0) {
  if (!std::isfinite(lon0) || lon0 < -180.0 || lon0 > 180.0)
    throw std::invalid_argument("projection centre: longitude must be in [-180, 180]");
  if (!std::isfinite(lat0) || lat0 < -90.0 || lat0 > 90.0)
    throw std::invalid_argument("projection centre: latitude must be in [-90, 90]");
  double x = 0.0, y = 0.0;
  wgs84_tm().Forward(lon0, lat0, lon0, x, y);
  return MapProjection(lon0, lat0, y);
}

Point MapProjection::forward(LonLat position) const {
  double x = 0.0, y = 0.0;
  wgs84_tm().Forward(lon0_, position.lat, position.lon, x, y);
  return {x, y - northing0_};
}

LonLat MapProjection::inverse(Point p) const {
  LonLat out;
  wgs84_tm().Reverse(lon0_, p.x, p.y + northing0_, out.lat, out.lon);
  return out;
}

std::string MapProjection::description() const {
  char text[160];
  std::snprintf(text, sizeof text, "transverse Mercator (WGS84), central meridian %.6g°%s, origin %.6g°%s, metres",
                std::abs(lon0_), lon0_ < 0 ? "W" : "E", std::abs(lat0_), lat0_ < 0 ? "S" : "N");
  return text;
}

}  // namespace covmap::mapgen
