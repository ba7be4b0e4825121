// The parts of report/audit_report.h that every report shares: option validation, the counts and
// the verdicts' words.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "report/audit_report.h"

#include "core/readable_numbers.h"

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
  if (!(html_lonlat_grid >= 1 && html_lonlat_grid <= 256)) return fail("html_lonlat_grid must be in [1, 256]");
  if (!basemap_url.empty()) {
    for (const char* part : {"{z}", "{x}", "{y}"})
      if (basemap_url.find(part) == std::string::npos) return fail("basemap_url must contain {z}, {x} and {y}");
    if (basemap_url.find_first_of("\"<>` \t\n\r") != std::string::npos)
      return fail("basemap_url must not contain quotes, angle brackets, backquotes or spaces");
  }
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
    case audit::SensorVerdict::kModelMisfit: return "model misfit (not judged)";
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

std::string model_fit_text(const audit::AuditResult& result) {
  const audit::ModelFit& f = result.model_fit;
  if (!f.known) return "";
  const std::string ratio = fixed(f.ratio, f.ratio < 10 ? 2 : 0);
  const std::string misfits = f.misfit_sensors == 0
                                  ? "no sensor lies in a region it does not explain"
                                  : plural(f.misfit_sensors, "sensor") + " (" + fixed(100.0 * f.misfit_area_share, 1) +
                                        " % of the covered area) lie in regions it does not explain and are not judged (model misfit)";
  const std::string reports =
      f.reports_median_p ? "; the reported sensors' median χ² tail probability is " + fixed(*f.reports_median_p, 3) +
                               " (about 0.5 or more where the model holds and the reports are right)"
                         : "";
  if (f.misfit)
    return "The map does not follow the path-loss model: the model draws its boundaries " + ratio +
           " times the mean square of free curves fitted to each (1 = as well as they do)" + reports + "; " + misfits +
           ". Verdicts elsewhere rest on a model the map only partly follows.";
  return "The map follows the path-loss model: the model draws its boundaries " + ratio +
         " times the mean square of free curves fitted to each (1 = as well as they do)" + reports + "; " + misfits + ".";
}

std::string alpha_text(const audit::AlphaEstimate& e) {
  if (!std::isfinite(e.high)) return "of at least " + fixed(e.low, 2) + " ± " + fixed(e.sigma_low, 2);
  if (e.high < 1.1 * e.low) {
    const double half = (e.high - e.low) / 2;
    const double sigma = std::sqrt(std::max(e.sigma_low, e.sigma_high) * std::max(e.sigma_low, e.sigma_high) + half * half);
    return "of " + fixed(e.low + half, 2) + " ± " + fixed(sigma, 2);
  }
  return "between " + fixed(e.low, 2) + " and " + fixed(e.high, 2);
}

std::string alpha_warning_text(const audit::AuditResult& result, std::optional<double> given_alpha) {
  if (!result.alpha_estimate || !result.alpha_estimate->disagrees || !given_alpha) return "";
  const audit::AlphaEstimate& e = *result.alpha_estimate;
  return "Check --alpha: the map and the reported powers imply a path-loss exponent " + alpha_text(e) + " (from " +
         plural(e.sensors, "sensor") + "), not " + fixed(*given_alpha, 2) + "; every weight and dB figure below depends on it.";
}

std::string reception_text(const audit::AuditResult& result) {
  if (!result.reception) return "";
  const audit::ReceptionLimit& r = *result.reception;
  std::string text = "Coverage ends at a reception limit (" + plural(r.sensors, "sensor") +
                     "): the strongest sensor reaches " + metres(r.range_m);
  if (r.range_sigma_m > 0) text += " ± " + metres(r.range_sigma_m);
  text += ", every other its weight times that";
  if (r.sensitivity_dbm)
    text += "; implied receiver sensitivity " + fixed(*r.sensitivity_dbm, 1) +
            " dBm relative to the transmit powers (up to the model's loss at 1 m)";
  return text + ".";
}

}  // namespace covmap::report
