#include <cpl_conv.h>
#include <ogr_srs_api.h>

#include <stdexcept>

#include "gis/crs_frame.h"
#include "gis/map_readers.h"
#include "io/input_error.h"

namespace covmap::gis::detail {
namespace {

// The spatial reference as WKT2, which PROJ reads without loss (WKT1 drops parts of some CRSs).
std::string wkt_of(OGRSpatialReferenceH srs) {
  char* text = nullptr;
  const char* const options[] = {"FORMAT=WKT2_2019", nullptr};
  if (OSRExportToWktEx(srs, &text, options) != OGRERR_NONE || !text) {
    CPLFree(text);
    return {};
  }
  std::string wkt(text);
  CPLFree(text);
  return wkt;
}

}  // namespace

DataCrs data_crs(OGRSpatialReferenceH srs, const std::string& label, bool planar) {
  DataCrs out;
  if (!srs) {
    if (!planar)
      throw io::InputError(label, 0, "",
                           "the data declare no coordinate reference system; give --planar if the coordinates are "
                           "metres in a plane, or assign the CRS they are in (e.g. ogr2ogr -a_srs EPSG:2056 out.gpkg in.shp)");
    return out;
  }
  const char* name = OSRGetName(srs);
  out.name = name ? name : "unnamed CRS";
  if (planar)
    throw io::InputError(label, 0, "",
                         "the data declare the coordinate reference system \"" + out.name +
                             "\", and covmap uses it: drop --planar (it is only for data without a CRS)");
  if (OSRIsGeographic(srs)) {
    out.kind = DataCrs::Kind::kGeographic;
    return out;
  }
  try {
    out.frame = projected_crs_frame(wkt_of(srs));
  } catch (const std::invalid_argument& e) {
    throw io::InputError(label, 0, "", e.what());
  }
  out.kind = DataCrs::Kind::kProjected;
  return out;
}

}  // namespace covmap::gis::detail
