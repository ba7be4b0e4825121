#include "io/local_projection.h"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/TransverseMercator.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace covmap::io {
namespace {

// One shared instance: construction computes the series coefficients, and the projection methods
// are const, so concurrent use is safe. k0 = 1 rather than UTM's 0.9996: covmap wants true
// metres at the centre of the map, not a compromise spread over a 6-degree zone.
const GeographicLib::TransverseMercator& wgs84_tm() {
  static const GeographicLib::TransverseMercator tm(GeographicLib::Constants::WGS84_a(),
                                                    GeographicLib::Constants::WGS84_f(), 1.0);
  return tm;
}

// "8.0084°E" / "3.5°W": four decimals is ~10 m, enough to recognise the place.
std::string degrees(double value, char positive, char negative) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.4f\u00b0%c", std::abs(value), value < 0 ? negative : positive);
  return buffer;
}

}  // namespace

LocalProjection LocalProjection::about(double lon0, double lat0) {
  if (!std::isfinite(lon0) || lon0 < -180.0 || lon0 > 180.0) {
    throw std::invalid_argument("LocalProjection: central longitude must be in [-180, 180] (got " + std::to_string(lon0) + ")");
  }
  if (!std::isfinite(lat0) || lat0 < -90.0 || lat0 > 90.0) {
    throw std::invalid_argument("LocalProjection: origin latitude must be in [-90, 90] (got " + std::to_string(lat0) + ")");
  }
  double x = 0.0, northing = 0.0;
  wgs84_tm().Forward(lon0, lat0, lon0, x, northing);
  return LocalProjection(lon0, lat0, northing);
}

Point LocalProjection::forward(double lon, double lat) const {
  double x = 0.0, y = 0.0;
  wgs84_tm().Forward(lon0_, lat, lon, x, y);
  return {x, y - northing0_};
}

ScaledPoint LocalProjection::forward_with_scale(double lon, double lat) const {
  double x = 0.0, y = 0.0, gamma = 0.0, k = 1.0;
  wgs84_tm().Forward(lon0_, lat, lon, x, y, gamma, k);
  // On the central meridian the scale is k0 = 1 by construction; the series gives 1 +- an ulp.
  // Saying 1 exactly there keeps "distortion 0 at the centre" true rather than nearly true.
  if (x == 0.0) k = 1.0;
  return {{x, y - northing0_}, k};
}

LonLat LocalProjection::inverse(Point p) const {
  LonLat out;
  wgs84_tm().Reverse(lon0_, p.x, p.y + northing0_, out.lat, out.lon);
  return out;
}

double LocalProjection::point_scale(double lon, double lat) const { return forward_with_scale(lon, lat).scale; }

double LocalProjection::point_scale_at(Point p) const {
  const LonLat g = inverse(p);
  return point_scale(g.lon, g.lat);
}

std::string LocalProjection::description() const {
  return "transverse Mercator (WGS84), central meridian " + degrees(lon0_, 'E', 'W') + ", origin " +
         degrees(lat0_, 'N', 'S') + ", metres";
}

}  // namespace covmap::io
