// gis/crs_frame.h against an independent implementation: GeographicLib's UTM (Karney's transverse
// Mercator series, not PROJ's code) for EPSG:32632, and closed forms (k = 0.9996 on UTM's central
// meridian; the LV95 false origin at the old Bern observatory).
#include "gis/crs_frame.h"

#include <GeographicLib/UTMUPS.hpp>
#include <gtest/gtest.h>

#include <stdexcept>

#include "io/local_projection.h"

namespace covmap::gis {
namespace {

constexpr double kMillimetre = 1e-3;

TEST(CrsFrame, UtmAgreesWithGeographicLib) {
  const auto frame = projected_crs_frame("EPSG:32632");
  EXPECT_EQ(frame->kind(), io::FrameKind::kProjectedCrs);
  EXPECT_EQ(frame->crs_code(), "EPSG:32632");
  for (double lon = 6.0; lon <= 12.0; lon += 1.5) {
    for (double lat = 44.0; lat <= 54.0; lat += 2.5) {
      int zone = 0;
      bool north = true;
      double x = 0, y = 0, gamma = 0, k = 0;
      GeographicLib::UTMUPS::Forward(lat, lon, zone, north, x, y, gamma, k, 32);
      const Point p = frame->forward(lon, lat);
      EXPECT_NEAR(p.x, x, kMillimetre) << lon << ", " << lat;
      EXPECT_NEAR(p.y, y, kMillimetre) << lon << ", " << lat;
      const io::LonLat back = frame->inverse(p);
      EXPECT_NEAR(back.lon, lon, 1e-10);
      EXPECT_NEAR(back.lat, lat, 1e-10);
      EXPECT_NEAR(frame->point_scale_at(p), k, 1e-9) << lon << ", " << lat;
    }
  }
}

TEST(CrsFrame, UtmScaleOnTheCentralMeridianIsItsK0) {
  const auto frame = projected_crs_frame("urn:ogc:def:crs:EPSG::32632");
  // PROJ's scale comes from numerical derivatives: good to about 1e-11.
  EXPECT_NEAR(frame->point_scale_at(frame->forward(9.0, 47.0)), 0.9996, 1e-9);
}

// swisstopo's approximate formulas from WGS84 to LV95 ("Approximate formulas for the
// transformation between Swiss projection coordinates and WGS84"), good to about a metre: a
// closed form independent of PROJ, its datum shift included.
Point swisstopo_lv95(double lon, double lat) {
  const double l = (lon * 3600 - 26782.5) / 10000, p = (lat * 3600 - 169028.66) / 10000;
  return {2600072.37 + 211455.93 * l - 10938.51 * l * p - 0.36 * l * p * p - 44.54 * l * l * l,
          1200147.07 + 308807.95 * p + 3745.25 * l * l + 76.63 * p * p - 194.56 * l * l * p + 119.79 * p * p * p};
}

TEST(CrsFrame, Lv95AgreesWithSwisstoposFormulas) {
  const auto frame = projected_crs_frame("EPSG:2056");
  for (double lon = 6.0; lon <= 10.4; lon += 0.55) {
    for (double lat = 45.9; lat <= 47.7; lat += 0.3) {
      const Point p = frame->forward(lon, lat), q = swisstopo_lv95(lon, lat);
      EXPECT_NEAR(p.x, q.x, 2.0) << lon << ", " << lat;
      EXPECT_NEAR(p.y, q.y, 2.0) << lon << ", " << lat;
    }
  }
  EXPECT_NE(frame->description().find("LV95"), std::string::npos);
  EXPECT_NE(frame->crs_wkt().find("2056"), std::string::npos);
  // The frame's reference lies in Switzerland (the CRS's area of use).
  EXPECT_GT(frame->reference().lon, 5.9);
  EXPECT_LT(frame->reference().lon, 10.5);
}

TEST(CrsFrame, WktOfTheCrsGivesTheSameFrame) {
  const auto by_code = projected_crs_frame("EPSG:2056");
  const auto by_wkt = projected_crs_frame(by_code->crs_wkt());
  const Point a = by_code->forward(7.4, 46.9), b = by_wkt->forward(7.4, 46.9);
  EXPECT_NEAR(a.x, b.x, kMillimetre);
  EXPECT_NEAR(a.y, b.y, kMillimetre);
}

void expect_refused(const std::string& definition, const std::string& says) {
  try {
    projected_crs_frame(definition);
    ADD_FAILURE() << definition << " was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
  }
}

TEST(CrsFrame, RefusesWhatItCannotUseAndSaysWhatToDo) {
  expect_refused("EPSG:4326", "geographic");
  expect_refused("EPSG:2227", "foot");          // California zone 3, US survey feet
  expect_refused("EPSG:2227", "ogr2ogr -t_srs");
  expect_refused("EPSG:99999999", "cannot read");
  expect_refused("not a crs at all", "cannot read");
  expect_refused("EPSG:4978", "not a projected");  // geocentric
}

TEST(CrsFrame, KindOfDefinitions) {
  EXPECT_EQ(crs_kind("EPSG:4326"), CrsKind::kGeographic);
  EXPECT_EQ(crs_kind("EPSG:4258"), CrsKind::kGeographic);
  EXPECT_EQ(crs_kind("EPSG:2154"), CrsKind::kProjected);
  EXPECT_EQ(crs_kind("EPSG:2056+5728"), CrsKind::kProjected);  // compound: by its horizontal part
  EXPECT_THROW(crs_kind("EPSG:99999999"), std::invalid_argument);
}

TEST(CrsFrame, ResolverServesGeoJsonDeclarations) {
  const io::CrsResolver resolve = proj_crs_resolver();
  EXPECT_EQ(resolve("urn:ogc:def:crs:EPSG::2154")->crs_code(), "EPSG:2154");
  EXPECT_THROW(resolve("EPSG:4258"), std::invalid_argument);
}

// The same interface, covmap's own local projection: its frame is kind kLocalProjection with no
// CRS to write (outputs then use WGS84).
TEST(CrsFrame, LocalProjectionIsAFrameWithoutACrs) {
  const io::LocalProjection local = io::LocalProjection::about(7.5, 46.9);
  const io::MapFrame& frame = local;
  EXPECT_EQ(frame.kind(), io::FrameKind::kLocalProjection);
  EXPECT_TRUE(frame.crs_wkt().empty());
  EXPECT_DOUBLE_EQ(frame.point_scale_at({0, 0}), 1.0);
}

}  // namespace
}  // namespace covmap::gis
