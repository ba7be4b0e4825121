#include "audit/boundary_samples.h"

#include <cmath>

namespace covmap::audit {
namespace {

// Points along the polyline `pts` every `spacing` of length (at most max_per_chain, spread evenly),
// starting half a spacing in; a polyline shorter than that still gives one.
template <typename Add>
void walk(const std::vector<Point>& pts, double spacing, int max_per_chain, Add add) {
  double length = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) length += std::hypot(pts[k + 1].x - pts[k].x, pts[k + 1].y - pts[k].y);
  const double step = max_per_chain > 0 ? std::max(spacing, length / max_per_chain) : spacing;
  if (pts.size() == 1 || !(step > 0)) {
    for (const auto& p : pts) add(p);
    return;
  }
  double next = 0.5 * step;
  double walked = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const double dx = pts[k + 1].x - pts[k].x, dy = pts[k + 1].y - pts[k].y;
    const double len = std::hypot(dx, dy);
    while (len > 0 && next <= walked + len) {
      const double t = (next - walked) / len;
      add({pts[k].x + t * dx, pts[k].y + t * dy});
      next += step;
    }
    walked += len;
  }
  if (walked < 0.5 * step) add(pts[pts.size() / 2]);
}

}  // namespace

std::vector<fitting::BoundarySample> sample_boundaries(const cleaning::CleanedMap& map, double spacing, double sigma,
                                                       int max_per_chain) {
  std::vector<fitting::BoundarySample> out;
  for (std::size_t c = 0; c < map.chains.size(); ++c) {
    const cleaning::BoundaryChain& chain = map.chains[c];
    if (chain.sensor_a == kNone || chain.sensor_b == kNone || chain.points.empty()) continue;
    walk(chain.points, spacing, max_per_chain,
         [&](Point p) { out.push_back({p, chain.sensor_a, chain.sensor_b, sigma, static_cast<int>(c)}); });
  }
  // Range edges: site_b = kNone; chain numbers continue after the map's chains.
  int piece_number = static_cast<int>(map.chains.size());
  for (const cleaning::RangeEdge& edge : map.range_edges)
    for (const auto& piece : edge.pieces) {
      walk(piece, spacing, max_per_chain, [&](Point p) { out.push_back({p, edge.sensor, kNone, sigma, piece_number}); });
      ++piece_number;
    }
  return out;
}

}  // namespace covmap::audit
