// Reading a coverage map happens in two passes. The first walks the GeoJSON and keeps, per feature,
// the sensor and the rings exactly as written, checking what can be checked on the numbers as read
// (structure, closing positions, lon/lat ranges, crs): in one pass over the text for a well-formed
// map, through the JSON library otherwise (io/coverage_map_drafts.h). The second needs the whole
// map, because the projection centre is the centre of all vertices: it projects, then validates
// each polygon in the plane where covmap will use it (io/coverage_map_rings.h), feature by feature
// on all cores (io/coverage_map_cells.h).
#include "io/coverage_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <unordered_set>

#include "io/coverage_map_cells.h"
#include "io/coverage_map_drafts.h"
#include "io/input_error.h"
#include "io/input_limits.h"
#include "io/text_util.h"

namespace covmap::io {
namespace {

using detail::FeatureDraft;
using detail::usable;

// Centre of the shortest longitude interval holding every value, in [-180, 180). Usually the middle
// of min and max; for a map across the antimeridian (values near both -180 and 180) the interval
// wraps around, and is the complement of the widest gap between neighbouring values.
double central_longitude(std::vector<double> lons) {
  const auto [lo, hi] = std::minmax_element(lons.begin(), lons.end());
  if (*hi - *lo <= 180.0) return (*lo + *hi) / 2;
  std::sort(lons.begin(), lons.end());
  double widest = lons.front() + 360.0 - lons.back();  // the gap across the antimeridian
  std::size_t after = 0;                                // the interval starts at lons[after]
  for (std::size_t i = 1; i < lons.size(); ++i) {
    if (lons[i] - lons[i - 1] > widest) {
      widest = lons[i] - lons[i - 1];
      after = i;
    }
  }
  const double start = lons[after];
  const double end = after == 0 ? lons.back() : lons[after - 1] + 360.0;
  double centre = (start + end) / 2;
  while (centre >= 180.0) centre -= 360.0;
  return centre;
}


// The worst |k/k_centre - 1| of a projected CRS over the bounding box of the usable vertices, on a
// grid of kScaleGridSide² points: k varies smoothly over a regional map, so the grid finds its
// extremes without asking PROJ about every vertex.
constexpr int kScaleGridSide = 17;

double crs_scale_distortion(const MapFrame& frame, const std::vector<FeatureDraft>& drafts) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const auto& d : drafts) {
    if (!usable(d)) continue;
    for (const auto& polygon : d.polygons)
      for (const auto& ring : polygon)
        for (const Point& p : ring) {
          x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
          y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        }
  }
  if (!(x0 <= x1 && y0 <= y1)) return 0.0;
  const double k_centre = frame.point_scale_at({(x0 + x1) / 2, (y0 + y1) / 2});
  double worst = 0.0;
  for (int i = 0; i < kScaleGridSide; ++i)
    for (int j = 0; j < kScaleGridSide; ++j) {
      const Point p{x0 + (x1 - x0) * i / (kScaleGridSide - 1), y0 + (y1 - y0) * j / (kScaleGridSide - 1)};
      worst = std::max(worst, std::abs(frame.point_scale_at(p) / k_centre - 1.0));
    }
  return worst;
}

LocalProjection projection_for(const std::vector<FeatureDraft>& drafts) {
  std::vector<double> lons;
  double lat_lo = std::numeric_limits<double>::infinity(), lat_hi = -lat_lo;
  for (const auto& d : drafts) {
    if (!usable(d)) continue;
    for (const auto& polygon : d.polygons) {
      for (const auto& ring : polygon) {
        for (const Point& p : ring) {
          lons.push_back(p.x);
          lat_lo = std::min(lat_lo, p.y);
          lat_hi = std::max(lat_hi, p.y);
        }
      }
    }
  }
  return LocalProjection::about(central_longitude(std::move(lons)), (lat_lo + lat_hi) / 2);
}

}  // namespace

namespace detail {

CoverageMap finish_coverage_map(FeatureDrafts first, const std::string& file, const CoverageMapOptions& options, int workers) {
  std::vector<FeatureDraft>& drafts = first.drafts;
  const CrsDeclarations& crs = first.crs;
  TopLevelCrs& top = first.top;
  const std::shared_ptr<const MapFrame> crs_frame = options.crs_frame ? options.crs_frame : top.frame;
  const bool crs_judged = !top.problems.empty();  // the declaration was read and refused
  if (options.max_sensors > 0) {
    std::unordered_set<std::string_view> sensors;
    for (const auto& d : drafts) sensors.insert(d.sensor);
    if (sensors.size() > options.max_sensors)
      throw InputError(file, 0, "", "the map names " + std::to_string(sensors.size()) + " sensors; one audit takes at most " +
                                        std::to_string(options.max_sensors) +
                                        " (the refinement would run for hours): split the map into regions");
  }
  std::size_t vertices = 0;
  for (const auto& d : drafts)
    for (const auto& polygon : d.polygons)
      for (const auto& ring : polygon) vertices += ring.size();
  if (vertices > kMaxMapVertices)
    throw InputError(file, 0, "",
                     std::to_string(vertices) + " vertices; covmap audits at most " + std::to_string(kMaxMapVertices) +
                         " per map (docs/RELIABILITY.md): simplify the cells or split the map into regions");
  std::vector<InputProblem> problems = std::move(top.problems);
  if (!options.crs_frame) {
    std::vector<InputProblem> declared = crs.problems(options.planar || top.plane || crs_frame || crs_judged);
    problems.insert(problems.end(), declared.begin(), declared.end());
  }
  // A crs problem means the numbers are not what the reader takes them for; validating the
  // geometry of misread coordinates would only bury the one message that matters.
  const bool check_geometry = problems.empty() && std::any_of(drafts.begin(), drafts.end(), usable);

  CoverageMap map;
  // Set for lon/lat input only: the vertices are then projected, each with its point scale.
  std::optional<LocalProjection> local;
  if (check_geometry && crs_frame) {
    map.frame = crs_frame;
    map.max_scale_distortion = crs_scale_distortion(*crs_frame, drafts);
  } else if (check_geometry && !options.planar && !top.plane) {
    local = projection_for(drafts);
    map.frame = std::make_shared<LocalProjection>(*local);
  }
  if (check_geometry) add_cells(drafts, local ? &*local : nullptr, map, workers > 0 ? workers : cell_workers(vertices));
  for (const auto& d : drafts)
    for (const auto& message : d.problems) problems.push_back({0, d.label, message});
  if (!problems.empty()) throw InputError(file, std::move(problems));
  return map;
}

}  // namespace detail

CoverageMap parse_coverage_map(std::string_view text, const std::string& file, const CoverageMapOptions& options) {
  if (options.crs_frame && options.planar)
    throw std::invalid_argument("CoverageMapOptions: planar and a CRS frame are mutually exclusive");
  // The fast path takes well-formed maps; anything else is read (and its problems worded) by the
  // reference, whose JSON document is freed before the second pass.
  std::optional<detail::FeatureDrafts> first = detail::read_features_fast(text, options);
  if (!first) first = detail::read_features_reference(text, file, options);
  return detail::finish_coverage_map(std::move(*first), file, options);
}

CoverageMap read_coverage_map(const std::filesystem::path& path, const CoverageMapOptions& options) {
  return parse_coverage_map(detail::read_text_file(path), path.string(), options);
}

}  // namespace covmap::io
