// Range edges that the fitted sensors do not bear out (audit_stages.h, drop_unfitted_range_edges).
#include <cmath>

#include "audit/audit_stages.h"
#include "audit/model_fit.h"
#include "audit/tolerances.h"

namespace covmap::audit::stages {

bool drop_unfitted_range_edges(RefinementSetup& setup, const fitting::RefineResult& refined, std::span<const double> area,
                               const AuditOptions& options, cleaning::CleanedMap& cleaned,
                               std::vector<std::string>& messages) {
  if (!refined.range || cleaned.range_edges.empty()) return false;
  const ModelFitResult fit = model_fit(cleaned, setup.samples, refined.sample_residual, area, setup.bin_size_m, options);
  std::vector<char> drop(setup.n, 0);
  std::size_t dropped = 0;
  for (const cleaning::RangeEdge& e : cleaned.range_edges) {
    const double ratio = fit.sensor_ratio[static_cast<std::size_t>(e.sensor)];
    if (std::isfinite(ratio) && ratio > tolerance::kRangeEdgeMisfitRatio) drop[e.sensor] = 1, ++dropped;
  }
  if (dropped == 0) return false;
  std::erase_if(setup.samples, [&](const fitting::BoundarySample& s) { return s.site_b == kNone && drop[s.site_a]; });
  std::erase_if(cleaned.range_edges, [&](const cleaning::RangeEdge& e) { return drop[e.sensor] != 0; });
  cleaned.report.range_edges = cleaned.range_edges.size();
  messages.push_back(std::to_string(dropped) +
                     " sensor(s) had an outside boundary shaped like a reach that the fitted sensors do not bear out "
                     "(e.g. the edge of a hole where a cell is missing); it is treated as the map's frame and the "
                     "sensors were refined again");
  return true;
}

}  // namespace covmap::audit::stages
