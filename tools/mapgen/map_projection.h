// covmap::mapgen::MapProjection — the plane in which the generator lays out bins, and lon/lat.
//
// Contract: MapProjection::about(lon0, lat0) is the transverse Mercator projection of the WGS84
// ellipsoid (GeographicLib::TransverseMercator, Krüger series, accurate to nanometres within
// thousands of kilometres of the central meridian) with central meridian lon0, scale factor exactly
// 1 on that meridian, no false easting, and northing counted from latitude lat0, so (lon0, lat0) is
// (0, 0); x east, y north, metres. It is the same plane as covmap::io::LocalProjection, so a map
// generated here and read back by covmap's readers lands on the generator's own coordinates.
// Why transverse Mercator: it is conformal (distance ratios, hence weighted-Voronoi ownership, are
// preserved locally), and square bins in it are how radio-planning tools rasterize (in UTM, the same
// projection with a different centre and scale). Accepted: finite lon0 in [-180, 180], lat0 in
// [-90, 90]; otherwise std::invalid_argument. forward() and inverse() agree to well below a
// micrometre over hundreds of kilometres.
#pragma once

#include <string>

#include "core/diagram.h"

namespace covmap::mapgen {

struct LonLat {
  double lon = 0.0;  // degrees east
  double lat = 0.0;  // degrees north
};

class MapProjection {
 public:
  static MapProjection about(double lon0, double lat0);

  Point forward(LonLat position) const;
  LonLat inverse(Point p) const;

  double lon0() const { return lon0_; }
  double lat0() const { return lat0_; }
  double northing0() const { return northing0_; }

  // "transverse Mercator (WGS84), central meridian 8.0084°E, origin 47.1044°N, metres".
  std::string description() const;

 private:
  MapProjection(double lon0, double lat0, double northing0) : lon0_(lon0), lat0_(lat0), northing0_(northing0) {}

  double lon0_ = 0.0;
  double lat0_ = 0.0;
  double northing0_ = 0.0;  // northing of lat0 on the central meridian, from the equator
};

}  // namespace covmap::mapgen
