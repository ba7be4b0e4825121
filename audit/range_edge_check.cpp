// Range edges that the fitted sensors do not bear out (audit_stages.h, check_range_edges).
#include <cmath>
#include <utility>

#include "audit/audit_stages.h"
#include "audit/model_fit.h"
#include "audit/tolerances.h"

namespace covmap::audit::stages {
namespace {

// Every sensor whose boundaries the fit draws worse than kRangeEdgeMisfitRatio (empty when the
// refinement left no residuals).
std::vector<char> unfitted(const std::vector<fitting::BoundarySample>& samples, const fitting::RefineResult& refined,
                           std::span<const double> area, double bin, const AuditOptions& options,
                           const cleaning::CleanedMap& cleaned) {
  if (refined.sample_residual.size() != samples.size()) return {};
  const ModelFitResult fit = model_fit(cleaned, samples, refined.sample_residual, area, bin, options);
  std::vector<char> out(fit.sensor_ratio.size(), 0);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = std::isfinite(fit.sensor_ratio[i]) && fit.sensor_ratio[i] > tolerance::kRangeEdgeMisfitRatio;
  return out;
}

}  // namespace

Messages check_range_edges(RefinementSetup& setup, fitting::RefineResult& refined, const MapCells& cells,
                           const AuditOptions& options, cleaning::CleanedMap& cleaned) {
  if (!refined.range || cleaned.range_edges.empty()) return {};
  const std::vector<char> before = unfitted(setup.samples, refined, cells.area, setup.bin_size_m, options, cleaned);
  std::vector<int> suspects;
  for (const cleaning::RangeEdge& e : cleaned.range_edges)
    if (!before.empty() && before[static_cast<std::size_t>(e.sensor)]) suspects.push_back(e.sensor);
  if (suspects.empty()) return {};
  std::vector<char> drop(setup.n, 0);
  for (int i : suspects) drop[static_cast<std::size_t>(i)] = 1;
  // Without the suspects' edges, refined again; kept only if the fit is better everywhere: fewer
  // sensors drawn badly, and none that was drawn well before.
  RefinementSetup without = setup;
  std::erase_if(without.samples, [&](const fitting::BoundarySample& s) { return s.site_b == kNone && drop[s.site_a]; });
  std::vector<cleaning::RangeEdge> kept;
  for (const cleaning::RangeEdge& e : cleaned.range_edges)
    if (!drop[e.sensor]) kept.push_back(e);
  Refinement again = refine_from(without, refined.sites, cells.centroids);
  std::swap(cleaned.range_edges, kept);
  const std::vector<char> after = unfitted(without.samples, again.refined, cells.area, setup.bin_size_m, options, cleaned);
  bool better = !after.empty();
  std::size_t count_before = 0, count_after = 0;
  for (std::size_t i = 0; better && i < after.size(); ++i) {
    count_before += before[i], count_after += after[i];
    if (after[i] && !before[i]) better = false;
  }
  if (!better || count_after >= count_before) {  // the edges were not the trouble: they stand
    std::swap(cleaned.range_edges, kept);
    return {};
  }
  cleaned.report.range_edges = cleaned.range_edges.size();
  setup = std::move(without);
  refined = std::move(again.refined);
  Messages messages = std::move(again.messages);
  messages.push_back(std::to_string(suspects.size()) +
                     " sensor(s) had an outside boundary shaped like a reach that the fitted sensors do not bear out "
                     "(e.g. the edge of a hole where a cell is missing); it is treated as the map's frame, and the "
                     "sensors refined again without it fit their boundaries");
  return messages;
}

}  // namespace covmap::audit::stages
