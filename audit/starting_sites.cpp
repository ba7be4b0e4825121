// Start values for audit()'s refinement: the tolerant estimates (start_values.h), each checked
// against the map's cells, and reported positions where the estimate had nothing better.
#include <algorithm>
#include <cmath>

#include "audit/audit_stages.h"

namespace covmap::audit::stages {

ReportedOf reported_in_map(std::span<const ReportedSensor> reported, const MapCells& cells) {
  ReportedOf reported_of;
  for (const ReportedSensor& r : reported)
    if (auto it = cells.index.find(r.id); it != cells.index.end()) reported_of[it->second] = &r;
  return reported_of;
}

StartingSites starting_sites(const SiteEstimates& estimates, const MapCells& cells, const MapRaster& raster,
                             const ReportedOf& reported_of) {
  StartingSites out;
  const std::size_t n = cells.centroids.size();
  const std::vector<Point>& centroids = cells.centroids;
  const Box& box = cells.box;
  // A site lies in its own region (or outside the map, for a sensor beyond the map's edge): an
  // estimate inside another sensor's cell is noise from short, poorly fitted arcs, and the cell's
  // centroid is the better start.
  const double extent_box = std::max(box.xmax - box.xmin, box.ymax - box.ymin);
  std::vector<Site>& start = out.sites;
  start = estimates.sites;
  int moved_to_centroid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int at = raster.label_at(start[i].x, start[i].y);
    const bool far = std::hypot(start[i].x - centroids[i].x, start[i].y - centroids[i].y) > extent_box;
    if ((at != kNone && at != static_cast<int>(i)) || far || !std::isfinite(start[i].x) || !std::isfinite(start[i].y)) {
      start[i].x = centroids[i].x, start[i].y = centroids[i].y;
      ++moved_to_centroid;
    }
  }
  if (moved_to_centroid)
    out.messages.push_back(std::to_string(moved_to_centroid) +
                       " tolerant estimates lay in another sensor's cell; those sensors start from their cell's centroid");
  for (auto [i, r] : reported_of)
    if (estimates.how[i] == EstimateSource::kCentroid) {
      start[i].x = r->position.x, start[i].y = r->position.y;
      out.messages.push_back("sensor '" + r->id + "': no junction or located neighbour; started from its reported position");
    }
  return out;
}

}  // namespace covmap::audit::stages
