// covmap::io::MapFrame — the plane covmap works in for one map, and the way from it to WGS84.
//
// Every map is audited in a plane of metres. Where that plane comes from decides how outputs find
// their way back to the earth:
//  - kLocalProjection: the map was lon/lat; covmap projected it with its own transverse Mercator
//    about the map's centre (io/local_projection.h). Outputs carry lon/lat (WGS84).
//  - kProjectedCrs: the map's data declared a projected CRS in metres (UTM, LV95, Lambert-93, …);
//    its coordinates are the plane, used as they are, and outputs can keep that CRS (gis/ builds
//    this frame through PROJ; io only sees the interface, so parsing links no PROJ).
// A planar map with no CRS at all (`--planar`) has no frame: there is no way back to the earth.
//
// Contract: forward() and inverse() are mutual inverses over the map's region; point_scale_at()
// is the scale (plane length / true length) of a short segment at a plane point, 1 at the frame's
// reference point for kLocalProjection. Implementations are immutable, so one frame may be shared
// by threads.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "core/diagram.h"

namespace covmap::io {

struct LonLat {
  double lon = 0.0;  // degrees east
  double lat = 0.0;  // degrees north
};

// A projected point with the point scale there (both come out of one evaluation).
struct ScaledPoint {
  Point point;
  double scale = 1.0;
};

enum class FrameKind {
  kLocalProjection,  // lon/lat input, projected by covmap about the map's centre
  kProjectedCrs,     // the data's own projected CRS, in metres
};

class MapFrame {
 public:
  virtual ~MapFrame() = default;

  virtual FrameKind kind() const = 0;
  // The plane point of a WGS84 position (degrees).
  virtual Point forward(double lon, double lat) const = 0;
  // The WGS84 position (degrees, lon in [-180, 180]) of a plane point.
  virtual LonLat inverse(Point p) const = 0;
  // The point scale of the plane at p (the same in every direction for a conformal projection;
  // for one that is not, the larger of the scales along the meridian and the parallel).
  virtual double point_scale_at(Point p) const = 0;
  // The reference point of the frame, in degrees: the centre of a local projection, the centre of
  // the map for a projected CRS. Longitudes near it are written without a jump at ±180°.
  virtual LonLat reference() const = 0;
  // For people: "transverse Mercator (WGS84), central meridian 8.0084°E, …" or
  // "CH1903+ / LV95 (EPSG:2056), metres".
  virtual std::string description() const = 0;
  // The CRS of the plane as WKT, for outputs that carry a CRS (GeoPackage); empty for a local
  // projection, whose outputs are written in WGS84 lon/lat instead.
  virtual std::string crs_wkt() const = 0;
  // "EPSG:2056" when the CRS has an authority code; empty otherwise.
  virtual std::string crs_code() const = 0;
};

// Turns the name of a declared CRS ("EPSG:2056", "urn:ogc:def:crs:EPSG::2056") into its frame;
// throws std::invalid_argument, with a sentence for people, for a CRS covmap cannot use (unknown,
// not in metres, geographic other than WGS84). gis/ makes one through PROJ.
using CrsResolver = std::function<std::shared_ptr<const MapFrame>(const std::string& declared)>;

// The "crs" name covmap writes (covmap-make-map) for planar metres without a CRS. The readers take
// a file declaring it as planar, as with --planar, so covmap reads what it writes.
inline constexpr std::string_view kPlaneCrsName = "covmap:local-plane-metres";

}  // namespace covmap::io
