#include "io/local_projection.h"

#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace covmap::io {
namespace {

// The oracle for lengths: geodesic distances on the WGS84 ellipsoid (Karney's algorithm), which
// share nothing with the transverse Mercator series under test.
double geodesic_m(LonLat a, LonLat b) {
  double s = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(a.lat, a.lon, b.lat, b.lon, s);
  return s;
}

LonLat geodesic_step(LonLat from, double azimuth_deg, double metres) {
  LonLat to;
  GeographicLib::Geodesic::WGS84().Direct(from.lat, from.lon, azimuth_deg, metres, to.lat, to.lon);
  return to;
}

double planar_m(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

TEST(LocalProjection, CentreMapsToOriginWithScaleOne) {
  const auto p = LocalProjection::about(8.0084, 47.1044);
  const auto o = p.forward(8.0084, 47.1044);
  EXPECT_EQ(o.x, 0.0);
  EXPECT_EQ(o.y, 0.0);
  EXPECT_EQ(p.point_scale(8.0084, 47.1044), 1.0);
  // Scale 1 along the whole central meridian, more than 1 away from it.
  for (const double lat : {-60.0, 0.0, 30.0, 47.1044, 70.0}) EXPECT_NEAR(p.point_scale(8.0084, lat), 1.0, 1e-15);
  EXPECT_GT(p.point_scale(8.6, 47.1044), 1.0 + 1e-6);
}

TEST(LocalProjection, AxesPointEastAndNorthInMetres) {
  const auto p = LocalProjection::about(8.0084, 47.1044);
  const LonLat centre{8.0084, 47.1044};
  // 1 km due east and due north along geodesics: about +1000 in x, resp. y.
  const auto east = p.forward(geodesic_step(centre, 90, 1000).lon, geodesic_step(centre, 90, 1000).lat);
  const auto north = p.forward(geodesic_step(centre, 0, 1000).lon, geodesic_step(centre, 0, 1000).lat);
  EXPECT_NEAR(east.x, 1000.0, 1e-3);
  EXPECT_NEAR(east.y, 0.0, 0.1);  // a geodesic heading east curves slightly south of the parallel
  EXPECT_NEAR(north.x, 0.0, 1e-6);
  EXPECT_NEAR(north.y, 1000.0, 1e-6);
}

TEST(LocalProjection, ForwardInverseRoundTripOver100km) {
  for (const auto& [lon0, lat0] : std::vector<std::pair<double, double>>{{8.0084, 47.1044}, {-70.6, -33.4}, {179.9, 64.8}, {0, 0}}) {
    const auto p = LocalProjection::about(lon0, lat0);
    double worst = 0.0;
    for (double x = -100e3; x <= 100e3; x += 12.5e3) {
      for (double y = -100e3; y <= 100e3; y += 12.5e3) {
        const LonLat g = p.inverse({x, y});
        EXPECT_GE(g.lon, -180.0);
        EXPECT_LE(g.lon, 180.0);
        const auto back = p.forward(g.lon, g.lat);
        worst = std::max(worst, planar_m(back, {x, y}));
      }
    }
    EXPECT_LT(worst, 1e-6) << "centre " << lon0 << ", " << lat0;
  }
}

TEST(LocalProjection, ConformalPointScaleMatchesGeodesicSteps) {
  // Conformal: at a point, every short step is scaled by the same k, and k is point_scale().
  const auto p = LocalProjection::about(8.0084, 47.1044);
  const LonLat at{9.1, 47.5};  // ~80 km east of the central meridian
  const double k = p.point_scale(at.lon, at.lat);
  const auto centre = p.forward(at.lon, at.lat);
  for (double azimuth = 0; azimuth < 360; azimuth += 22.5) {
    const LonLat q = geodesic_step(at, azimuth, 10.0);
    EXPECT_NEAR(planar_m(p.forward(q.lon, q.lat), centre) / 10.0, k, 2e-6) << "azimuth " << azimuth;
  }
}

TEST(LocalProjection, DistanceRatiosPreservedWithinReportedDistortion) {
  // A map of about 150 km x 200 km. The reported distortion is max |k/k0 - 1| over its points;
  // every planar distance is the geodesic one times a factor in [1, 1 + distortion] (k >= 1 = k0
  // in transverse Mercator), so a ratio of two distances is off by at most a factor
  // (1 + distortion) either way. The allowance for the chord-vs-curve difference is far smaller.
  const LonLat centre{8.0084, 47.1044};
  const auto p = LocalProjection::about(centre.lon, centre.lat);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> dlon(-1.0, 1.0), dlat(-0.9, 0.9);
  std::vector<LonLat> points;
  double distortion = 0.0;
  for (int i = 0; i < 60; ++i) {
    points.push_back({centre.lon + dlon(random), centre.lat + dlat(random)});
    distortion = std::max(distortion, std::abs(p.point_scale(points.back().lon, points.back().lat) - 1.0));
  }
  ASSERT_GT(distortion, 1e-5);  // the map is big enough for the bound to mean something
  ASSERT_LT(distortion, 1e-4);
  constexpr double kChordAllowance = 1e-8;
  for (std::size_t i = 0; i + 2 < points.size(); i += 3) {
    const LonLat a = points[i], b = points[i + 1], c = points[i + 2];
    const auto pa = p.forward(a.lon, a.lat), pb = p.forward(b.lon, b.lat), pc = p.forward(c.lon, c.lat);
    const double scale_ab = planar_m(pa, pb) / geodesic_m(a, b);
    const double scale_ac = planar_m(pa, pc) / geodesic_m(a, c);
    EXPECT_GE(scale_ab, 1.0 - kChordAllowance);
    EXPECT_LE(scale_ab, 1.0 + distortion + kChordAllowance);
    const double ratio_error = scale_ab / scale_ac;  // (|ab|/|ac|) / (s_ab/s_ac)
    EXPECT_LE(std::abs(ratio_error - 1.0), distortion * (1 + distortion) + kChordAllowance);
  }
}

TEST(LocalProjection, Description) {
  EXPECT_EQ(LocalProjection::about(8.0084, 47.1044).description(),
            "transverse Mercator (WGS84), central meridian 8.0084\u00b0E, origin 47.1044\u00b0N, metres");
  EXPECT_EQ(LocalProjection::about(-3.5, -33.9).description(),
            "transverse Mercator (WGS84), central meridian 3.5000\u00b0W, origin 33.9000\u00b0S, metres");
}

TEST(LocalProjection, RejectsCentreOutOfRange) {
  EXPECT_THROW(LocalProjection::about(181, 0), std::invalid_argument);
  EXPECT_THROW(LocalProjection::about(0, -90.5), std::invalid_argument);
  EXPECT_THROW(LocalProjection::about(NAN, 0), std::invalid_argument);
}

}  // namespace
}  // namespace covmap::io
