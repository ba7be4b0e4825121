#include "gis/crs_frame.h"

#include <proj.h>

#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace covmap::gis {
namespace {

// PROJ objects with their owner's release function, so every early return frees them.
struct ContextDeleter {
  void operator()(PJ_CONTEXT* c) const { proj_context_destroy(c); }
};
struct PjDeleter {
  void operator()(PJ* p) const { proj_destroy(p); }
};
using Context = std::unique_ptr<PJ_CONTEXT, ContextDeleter>;
using Pj = std::unique_ptr<PJ, PjDeleter>;

std::string quoted(const std::string& text) {
  return "\"" + (text.size() > 80 ? text.substr(0, 77) + "..." : text) + "\"";
}

// The CRS a definition names, without the parts covmap does not use: a bound CRS (WKT1 with
// TOWGS84) by its source, a compound CRS by its horizontal part.
Pj read_crs(PJ_CONTEXT* ctx, const std::string& definition) {
  Pj crs(proj_create(ctx, definition.c_str()));
  if (!crs) throw std::invalid_argument("PROJ cannot read the coordinate reference system " + quoted(definition));
  if (proj_get_type(crs.get()) == PJ_TYPE_BOUND_CRS) crs.reset(proj_get_source_crs(ctx, crs.get()));
  if (crs && proj_get_type(crs.get()) == PJ_TYPE_COMPOUND_CRS) crs.reset(proj_crs_get_sub_crs(ctx, crs.get(), 0));
  if (!crs) throw std::invalid_argument("PROJ cannot read the horizontal part of " + quoted(definition));
  return crs;
}

CrsKind kind_of(const PJ* crs) {
  switch (proj_get_type(crs)) {
    case PJ_TYPE_GEOGRAPHIC_2D_CRS:
    case PJ_TYPE_GEOGRAPHIC_3D_CRS:
    case PJ_TYPE_GEOGRAPHIC_CRS: return CrsKind::kGeographic;
    case PJ_TYPE_PROJECTED_CRS: return CrsKind::kProjected;
    default: return CrsKind::kOther;
  }
}

std::string code_of(const PJ* crs) {
  const char* auth = proj_get_id_auth_name(crs, 0);
  const char* code = proj_get_id_code(crs, 0);
  return auth && code ? std::string(auth) + ":" + code : std::string();
}

// The name and unit of the CRS's first axis ("metre", 1.0).
std::pair<std::string, double> axis_unit(PJ_CONTEXT* ctx, const PJ* crs) {
  Pj cs(proj_crs_get_coordinate_system(ctx, crs));
  const char* unit = nullptr;
  double factor = 0.0;
  if (!cs || !proj_cs_get_axis_info(ctx, cs.get(), 0, nullptr, nullptr, nullptr, &factor, &unit, nullptr, nullptr))
    return {"unknown unit", 0.0};
  return {unit ? unit : "unknown unit", factor};
}

// The middle of the CRS's area of use (longitudes across the antimeridian handled), or (0, 0).
io::LonLat area_centre(PJ_CONTEXT* ctx, const PJ* crs) {
  double west = 0, south = 0, east = 0, north = 0;
  if (!proj_get_area_of_use(ctx, crs, &west, &south, &east, &north, nullptr) ||
      west < -180.0 || east > 180.0)
    return {};
  if (east < west) east += 360.0;
  double lon = (west + east) / 2;
  if (lon > 180.0) lon -= 360.0;
  return {lon, (south + north) / 2};
}

// The CRS's map projection as a plain PROJ operation (geodetic radians to metres), made from its
// PROJ string without the "+type=crs" that would make it a CRS again; null if it has none.
Pj bare_projection(PJ_CONTEXT* ctx, const PJ* crs) {
  const char* text = proj_as_proj_string(ctx, crs, PJ_PROJ_4, nullptr);
  if (!text) return nullptr;
  std::string definition = text;
  if (const auto at = definition.find(" +type=crs"); at != std::string::npos) definition.erase(at, 10);
  return Pj(proj_create(ctx, definition.c_str()));
}

class ProjectedCrsFrame final : public io::MapFrame {
 public:
  explicit ProjectedCrsFrame(const std::string& definition) : ctx_(proj_context_create()) {
    proj_log_level(ctx_.get(), PJ_LOG_NONE);
    crs_ = read_crs(ctx_.get(), definition);
    name_ = proj_get_name(crs_.get()) ? proj_get_name(crs_.get()) : definition;
    code_ = code_of(crs_.get());
    const CrsKind kind = kind_of(crs_.get());
    if (kind == CrsKind::kGeographic)
      throw std::invalid_argument(quoted(name_) +
                                  " is geographic (longitude/latitude): give the data as WGS84 lon/lat, e.g. "
                                  "ogr2ogr -t_srs EPSG:4326, or in a projected CRS in metres");
    if (kind != CrsKind::kProjected)
      throw std::invalid_argument(quoted(name_) + " is not a projected coordinate reference system; covmap needs a map "
                                                  "in lon/lat or in a projected CRS in metres");
    const auto [unit, factor] = axis_unit(ctx_.get(), crs_.get());
    if (factor != 1.0)
      throw std::invalid_argument(quoted(name_) + " measures in " + unit +
                                  "; covmap works in metres: reproject the data to a projected CRS in metres, e.g. "
                                  "ogr2ogr -t_srs EPSG:<code> (the UTM zone or national grid in metres)");
    Pj wgs84(proj_create(ctx_.get(), "EPSG:4326"));
    Pj raw(proj_create_crs_to_crs_from_pj(ctx_.get(), crs_.get(), wgs84.get(), nullptr, nullptr));
    if (!raw) throw std::invalid_argument("PROJ has no transformation from " + quoted(name_) + " to WGS84");
    // x = east, y = north on the CRS side; lon, lat in degrees on the WGS84 side.
    to_wgs84_.reset(proj_normalize_for_visualization(ctx_.get(), raw.get()));
    if (!to_wgs84_) throw std::invalid_argument("PROJ cannot normalize the axes of " + quoted(name_));
    reference_ = area_centre(ctx_.get(), crs_.get());
    // The projection alone, for proj_factors: asked about the CRS itself, PROJ rebuilds the
    // operation on every call (milliseconds each); the bare projection answers in microseconds.
    conversion_ = bare_projection(ctx_.get(), crs_.get());
  }

  io::FrameKind kind() const override { return io::FrameKind::kProjectedCrs; }

  Point forward(double lon, double lat) const override {
    const PJ_COORD c = trans(PJ_INV, lon, lat);
    return {c.xy.x, c.xy.y};
  }

  io::LonLat inverse(Point p) const override {
    const PJ_COORD c = trans(PJ_FWD, p.x, p.y);
    return {c.lp.lam, c.lp.phi};
  }

  double point_scale_at(Point p) const override {
    if (!conversion_) return std::numeric_limits<double>::quiet_NaN();
    const io::LonLat g = inverse(p);
    std::lock_guard<std::mutex> lock(mutex_);
    // proj_factors takes the base geographic CRS's lon/lat in radians; WGS84 differs from it by a
    // datum shift of metres, which changes the scale by far less than the digits reported.
    const PJ_FACTORS f = proj_factors(conversion_.get(), proj_coord(g.lon * M_PI / 180, g.lat * M_PI / 180, 0, 0));
    if (proj_errno(conversion_.get()) != 0) {
      proj_errno_reset(conversion_.get());
      return std::numeric_limits<double>::quiet_NaN();
    }
    return std::max(f.meridional_scale, f.parallel_scale);
  }

  io::LonLat reference() const override { return reference_; }

  std::string description() const override {
    return name_ + (code_.empty() ? "" : " (" + code_ + ")") + ", metres";
  }

  std::string crs_wkt() const override {
    std::lock_guard<std::mutex> lock(mutex_);
    const char* wkt = proj_as_wkt(ctx_.get(), crs_.get(), PJ_WKT2_2019, nullptr);
    return wkt ? wkt : "";
  }

  std::string crs_code() const override { return code_; }

 private:
  PJ_COORD trans(PJ_DIRECTION direction, double a, double b) const {
    std::lock_guard<std::mutex> lock(mutex_);
    PJ_COORD c = proj_trans(to_wgs84_.get(), direction, proj_coord(a, b, 0, 0));
    if (proj_errno(to_wgs84_.get()) != 0) {
      proj_errno_reset(to_wgs84_.get());
      c.xy.x = c.xy.y = std::numeric_limits<double>::quiet_NaN();
    }
    return c;
  }

  Context ctx_;
  Pj crs_;
  Pj to_wgs84_;
  Pj conversion_;  // the map projection of crs_, without datum or axis handling
  std::string name_;
  std::string code_;
  io::LonLat reference_;
  mutable std::mutex mutex_;
};

}  // namespace

CrsKind crs_kind(const std::string& definition) {
  Context ctx(proj_context_create());
  proj_log_level(ctx.get(), PJ_LOG_NONE);
  return kind_of(read_crs(ctx.get(), definition).get());
}

std::shared_ptr<const io::MapFrame> projected_crs_frame(const std::string& definition) {
  return std::make_shared<ProjectedCrsFrame>(definition);
}

io::CrsResolver proj_crs_resolver() { return [](const std::string& declared) { return projected_crs_frame(declared); }; }

}  // namespace covmap::gis
