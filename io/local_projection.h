// covmap::io::LocalProjection — the plane in which covmap works on a map given in lon/lat.
//
// Contract: LocalProjection::about(lon0, lat0) is a transverse Mercator projection of the WGS84
// ellipsoid (GeographicLib's TransverseMercator, accurate to a few nanometres within thousands of
// kilometres of the central meridian) with central meridian lon0, scale exactly 1 on that meridian,
// no false easting, and northing measured from latitude lat0, so (lon0, lat0) maps to (0, 0).
// x grows to the east and y to the north, in metres. forward() and inverse() are mutual inverses
// (to well below a micrometre over hundreds of kilometres). Accepted: lon0 in [-180, 180], lat0 in
// [-90, 90], both finite; anything else throws std::invalid_argument. forward() expects lat in
// [-90, 90] and any finite lon (differences from lon0 are reduced to [-180, 180]).
//
// Why conformal: a point belongs to the site minimizing |p - s| / w(s), so the multiplicatively
// weighted Voronoi diagram depends only on ratios of distances measured from a common point. A
// conformal projection scales every direction at a point by the same factor k (the point scale), so
// it preserves those ratios to first order around any point; an equal-area or equidistant
// projection would stretch one direction against another and move every bisector. The error that
// remains is the variation of k across the map: a distance on the plane is the true distance times
// some k between the smallest and largest k along the way, so a ratio of two distances is off by at
// most about 2 * max |k / k_centre - 1|. Readers report that worst distortion over the vertices they
// project (k grows with the distance from the central meridian, roughly 1 + x^2 / (2 R^2): 3e-5 at
// 50 km, 1.2e-4 at 100 km), so a caller can judge whether the map is small enough to be treated as
// plane.
#pragma once

#include <string>

#include "core/diagram.h"
#include "io/map_frame.h"

namespace covmap::io {

class LocalProjection final : public MapFrame {
 public:
  // The projection centred on (lon0, lat0), in degrees. Throws std::invalid_argument when out of range.
  static LocalProjection about(double lon0, double lat0);

  FrameKind kind() const override { return FrameKind::kLocalProjection; }
  // Planar metres of a geographic position (degrees).
  Point forward(double lon, double lat) const override;
  // forward() and point_scale() at once, for readers that project many vertices.
  ScaledPoint forward_with_scale(double lon, double lat) const;
  // Geographic position (degrees, lon in [-180, 180]) of planar metres.
  LonLat inverse(Point p) const override;
  // The point scale k of the projection at (lon, lat): planar length / true length of a short
  // segment there, the same in every direction. 1 on the central meridian.
  double point_scale(double lon, double lat) const;
  double point_scale_at(Point p) const override;
  LonLat reference() const override { return {lon0_, lat0_}; }

  double lon0() const { return lon0_; }
  double lat0() const { return lat0_; }
  // Northing of (lon0, lat0) from the equator: the false northing is its negative.
  double northing0() const { return northing0_; }

  // "transverse Mercator (WGS84), central meridian 8.0084°E, origin 47.1044°N, metres".
  std::string description() const override;
  std::string crs_wkt() const override { return {}; }
  std::string crs_code() const override { return {}; }

 private:
  LocalProjection(double lon0, double lat0, double northing0) : lon0_(lon0), lat0_(lat0), northing0_(northing0) {}

  double lon0_ = 0.0;
  double lat0_ = 0.0;
  double northing0_ = 0.0;  // northing of lat0 on the central meridian, measured from the equator
};

}  // namespace covmap::io
