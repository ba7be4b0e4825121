#include "audit/boundary_samples.h"

#include <cmath>

namespace covmap::audit {

std::vector<fitting::BoundarySample> sample_boundaries(const cleaning::CleanedMap& map, double spacing, double sigma,
                                                       int max_per_chain) {
  std::vector<fitting::BoundarySample> out;
  for (std::size_t c = 0; c < map.chains.size(); ++c) {
    const cleaning::BoundaryChain& chain = map.chains[c];
    if (chain.sensor_a == kNone || chain.sensor_b == kNone || chain.points.empty()) continue;
    auto add = [&](Point p) {
      out.push_back({p, chain.sensor_a, chain.sensor_b, sigma, static_cast<int>(c)});
    };
    // Walk the polyline; emit a point each `spacing` of length, starting half a spacing in.
    const auto& pts = chain.points;
    double length = 0.0;
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) length += std::hypot(pts[k + 1].x - pts[k].x, pts[k + 1].y - pts[k].y);
    const double step = max_per_chain > 0 ? std::max(spacing, length / max_per_chain) : spacing;
    if (pts.size() == 1 || !(step > 0)) {
      for (const auto& p : pts) add(p);
      continue;
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
    if (walked < 0.5 * step) add(pts[pts.size() / 2]);  // a short chain still counts once
  }
  return out;
}

}  // namespace covmap::audit
