// The parts of report/audit_report.h that every report shares: option validation, the counts and
// the verdicts' words.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "report/audit_report.h"

namespace covmap::report {

bool AuditRenderOptions::is_valid(std::string* why) const {
  const auto fail = [&](const char* reason) {
    if (why) *why = reason;
    return false;
  };
  // Upper bounds keep a sampled arc a recognisable polygon (an arc of up to 360 degrees needs at
  // least a few segments) and a picture drawable; lower bounds keep the output finite.
  if (!(arc_step_degrees > 0 && arc_step_degrees <= 45)) return fail("arc_step_degrees must be in (0, 45]");
  if (!(arc_deviation > 0 && arc_deviation <= 0.1)) return fail("arc_deviation must be in (0, 0.1]");
  if (!(geographic_line_step > 0 && geographic_line_step <= 1)) return fail("geographic_line_step must be in (0, 1]");
  if (!(html_width_px >= 16 && html_width_px <= 100000)) return fail("html_width_px must be in [16, 100000]");
  if (!(html_margin >= 0 && html_margin <= 1)) return fail("html_margin must be in [0, 1]");
  if (!(html_grid_px > 0 && html_grid_px <= 1)) return fail("html_grid_px must be in (0, 1]");
  if (!(html_simplify_px >= 0 && html_simplify_px <= 10)) return fail("html_simplify_px must be in [0, 10]");
  // The picture's integer coordinates must stay exact in a double and short in the file.
  if (html_width_px / html_grid_px > 1e7) return fail("html_width_px / html_grid_px must not exceed 1e7");
  return true;
}

std::size_t AuditVerdictCounts::of(audit::SensorVerdict verdict) const {
  for (std::size_t i = 0; i < by_verdict.size(); ++i)
    if (audit::kAllSensorVerdicts[i] == verdict) return by_verdict[i];
  return 0;
}

AuditVerdictCounts count_verdicts(std::span<const audit::SensorAudit> sensors) {
  AuditVerdictCounts c;
  c.sensors = sensors.size();
  for (const auto& s : sensors) {
    c.in_map += s.in_map ? 1 : 0;
    c.reported += s.reported ? 1 : 0;
    const auto* at = std::find(std::begin(audit::kAllSensorVerdicts), std::end(audit::kAllSensorVerdicts), s.verdict);
    if (at == std::end(audit::kAllSensorVerdicts))
      throw std::logic_error("count_verdicts: a verdict missing from audit::kAllSensorVerdicts");
    ++c.by_verdict[static_cast<std::size_t>(at - std::begin(audit::kAllSensorVerdicts))];
  }
  return c;
}

std::string_view verdict_words(audit::SensorVerdict verdict) {
  // No default: a new verdict must be named here (report/ compiles with -Werror=switch).
  switch (verdict) {
    case audit::SensorVerdict::kUnreported: return "in the map but not reported";
    case audit::SensorVerdict::kConsistent: return "consistent";
    case audit::SensorVerdict::kInconsistent: return "inconsistent";
    case audit::SensorVerdict::kUndetermined: return "undetermined (not judged)";
    case audit::SensorVerdict::kNotInMap: return "reported but not in the map";
  }
  throw std::logic_error("verdict_words: a verdict outside the enumeration");
}

std::string verdict_counts_text(const AuditVerdictCounts& counts) {
  std::string text;
  for (std::size_t i = 0; i < counts.by_verdict.size(); ++i) {
    if (i) text += ", ";
    text += std::to_string(counts.by_verdict[i]);
    text += ' ';
    text += verdict_words(audit::kAllSensorVerdicts[i]);
  }
  return text;
}

std::size_t cleaning_repairs(const cleaning::CleaningReport& r) {
  return r.junctions_merged + r.gaps_closed + r.overlaps_resolved + r.short_chains_dropped + r.nodes_snapped;
}

}  // namespace covmap::report
