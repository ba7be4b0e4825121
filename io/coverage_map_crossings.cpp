#include "io/coverage_map_crossings.h"

#include <utility>

#include "core/orientation.h"
#include "io/segment_sweep.h"

namespace covmap::io::detail {

bool properly_cross(Point p1, Point p2, Point q1, Point q2) {
  const int o1 = orientation(p1, p2, q1);
  const int o2 = orientation(p1, p2, q2);
  if (o1 == 0 || o2 == 0 || o1 == o2) return false;
  const int o3 = orientation(q1, q2, p1);
  const int o4 = orientation(q1, q2, p2);
  return o3 != 0 && o4 != 0 && o3 != o4;
}

std::optional<Crossing> find_crossing(std::span<const std::vector<Point>> rings) {
  // Edges numbered ring by ring, edge by edge, so index order is EdgeRef order.
  std::size_t count = 0;
  for (const auto& ring : rings) count += ring.size();
  std::vector<Segment> edges;
  std::vector<EdgeRef> refs;
  edges.reserve(count);
  refs.reserve(count);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
      refs.push_back({r, i});
    }
  }
  // Accepting exactly the properly crossing pairs is the case io/segment_sweep.h proves: a crossing
  // is found whenever one exists, touching and overlapping edges notwithstanding.
  const auto end = [&](std::size_t k, std::size_t step) {
    const auto& ring = rings[refs[k].ring];
    return ring[(refs[k].edge + step) % ring.size()];
  };
  const auto pair = find_adjacent_pair(std::move(edges), [&](std::size_t i, std::size_t j) {
    return properly_cross(end(i, 0), end(i, 1), end(j, 0), end(j, 1));
  });
  if (!pair) return std::nullopt;
  return Crossing{refs[pair->first], refs[pair->second]};
}

}  // namespace covmap::io::detail
