#include "io/coverage_map_cells.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

#include "core/parallel.h"
#include "io/coverage_map_rings.h"

namespace covmap::io::detail {
namespace {

// What one feature contributes; combined in feature order by add_cells.
struct CellSlot {
  bool made = false;  // the feature was usable, so it has a cell (possibly with problems)
  MapCell cell;
  std::size_t vertices = 0;
  double distortion = 0.0;  // worst |k / k_centre - 1| over its projected vertices
  std::exception_ptr error;
};

void build_cell(FeatureDraft& d, const LocalProjection* local, double k_centre, CellSlot& slot) {
  MapCell& cell = slot.cell;
  cell.sensor = d.sensor;
  cell.name = d.name;
  cell.feature = d.index;
  for (std::size_t k = 0; k < d.polygons.size(); ++k) {
    std::vector<RingInput> rings;
    rings.reserve(d.polygons[k].size());
    bool projected = true;
    for (RawRing& raw : d.polygons[k]) {
      RingInput& ring = rings.emplace_back();
      ring.projected.reserve(raw.size());
      for (const Point& p : raw) {
        if (!local) {
          ring.projected.push_back(p);
          continue;
        }
        const ScaledPoint q = local->forward_with_scale(p.x, p.y);
        slot.distortion = std::max(slot.distortion, std::abs(q.scale / k_centre - 1.0));
        ring.projected.push_back(q.point);
        projected = projected && std::isfinite(q.point.x) && std::isfinite(q.point.y);
      }
      ring.read = std::move(raw);
    }
    if (!projected) {
      // Only a map reaching 90 degrees of longitude from its centre gets here.
      d.problems.push_back((d.multi ? "polygon " + std::to_string(k) : std::string("the polygon")) +
                           " lies too far from the map centre for " + local->description() +
                           "; covmap audits regional maps, not continents");
      continue;
    }
    if (auto polygon = make_map_polygon(rings, {k, d.multi}, d.problems)) {
      slot.vertices += polygon->outer.size();
      for (const auto& hole : polygon->holes) slot.vertices += hole.size();
      cell.polygons.push_back(std::move(*polygon));
    }
  }
  slot.made = true;
}

}  // namespace

void add_cells(std::vector<FeatureDraft>& drafts, const LocalProjection* local, CoverageMap& map, int workers) {
  const double k_centre = local ? local->point_scale(local->lon0(), local->lat0()) : 1.0;
  std::vector<CellSlot> slots(drafts.size());
  parallel_items(drafts.size(), workers, [&](std::size_t i) {
    FeatureDraft& d = drafts[i];
    // An exception must not leave a worker thread (std::terminate); it is rethrown below.
    try {
      if (usable(d)) build_cell(d, local, k_centre, slots[i]);
      d.polygons.clear();
      d.polygons.shrink_to_fit();
    } catch (...) {
      slots[i].error = std::current_exception();
    }
  });
  for (CellSlot& slot : slots) {
    if (slot.error) std::rethrow_exception(slot.error);
    if (!slot.made) continue;
    map.cells.push_back(std::move(slot.cell));
    map.vertex_count += slot.vertices;
    if (local) map.max_scale_distortion = std::max(map.max_scale_distortion, slot.distortion);
  }
}

int cell_workers(std::size_t vertices) { return worker_count(vertices); }

}  // namespace covmap::io::detail
