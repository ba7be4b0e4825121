#include "cli/audit_summary.h"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <ostream>
#include <vector>

#include "core/readable_numbers.h"

namespace covmap::cli {
namespace {

// Whether the summary lists the sensor by name with its reason: every verdict a planner must act on
// or look at. No default: a new verdict must be decided here (cli/ compiles with -Werror=switch).
bool listed_by_name(audit::SensorVerdict verdict) {
  switch (verdict) {
    case audit::SensorVerdict::kInconsistent:
    case audit::SensorVerdict::kUndetermined:
    case audit::SensorVerdict::kNotInMap:
    case audit::SensorVerdict::kModelMisfit: return true;
    case audit::SensorVerdict::kConsistent:
    case audit::SensorVerdict::kUnreported: return false;
  }
  return true;
}

}  // namespace

// One line that accounts for every sensor (the counts by verdict add up to the total), the
// agreement of the diagrams, then the sensors worth a look, by name under their verdict.
void print_audit_summary(std::ostream& out, const job::AuditRequest& request, const job::AuditedMap& audited) {
  const std::string map = request.inputs.map.string();
  const audit::AuditResult& result = audited.result;
  const report::AuditVerdictCounts& counts = audited.counts;
  // A wrong alpha, then a map the model does not explain, are said first: the verdicts below are
  // read in their light.
  if (const std::string alpha = report::alpha_warning_text(result, request.settings.alpha); !alpha.empty())
    out << map << ": " << alpha << "\n";
  if (result.model_fit.misfit) out << map << ": " << report::model_fit_text(result) << "\n";
  out << map << ": " << counts.sensors << " sensors (" << counts.in_map << " with a cell in the map, "
      << counts.sensors - counts.in_map << " reported without one; " << counts.reported << " reported): "
      << report::verdict_counts_text(counts) << "; refined diagram agrees with the map on "
      << fixed(100.0 * result.refined_agreement.mean_iou, 1) << " % of its area";
  if (result.reported_agreement)
    out << " (reported sensors: " << fixed(100.0 * result.reported_agreement->mean_iou, 1) << " %)";
  out << " -> " << request.outputs.folder.string() << "\n";
  if (!result.model_fit.misfit && result.model_fit.known) out << "  " << report::model_fit_text(result) << "\n";
  if (const std::string reach = report::reception_text(result); !reach.empty()) out << "  " << reach << "\n";
  for (const audit::SensorVerdict verdict : audit::kAllSensorVerdicts) {
    if (!listed_by_name(verdict) || counts.of(verdict) == 0) continue;
    out << "  " << report::verdict_words(verdict) << ":\n";
    for (const auto& s : result.sensors)
      if (s.verdict == verdict) out << "    " << s.id << ": " << s.reason << "\n";
  }
}

bool is_finding(const AuditCommandOptions& options, const job::AuditedMap& audited) {
  return options.fail_on_inconsistent && audited.counts.of(audit::SensorVerdict::kInconsistent) > 0;
}

job::AuditJobHooks stderr_hooks(bool quiet) {
  job::AuditJobHooks hooks;
  hooks.note = [](const std::string& note) { std::cerr << "covmap audit: note: " << note << "\n"; };
  hooks.warning = [](const std::filesystem::path& file, const std::string& finding) {
    std::cerr << "covmap audit: warning: " << file.string() << ": " << finding << "\n";
  };
  if (quiet) return hooks;
  const auto t0 = std::chrono::steady_clock::now();
  hooks.progress = [t0](const std::string& what) {
    std::cerr << "covmap audit: " << what << " ("
              << seconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()) << ")\n";
  };
  return hooks;
}

}  // namespace covmap::cli
