// The order of attention (report/audit_report.h): worst verdicts first, then the strongest evidence.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "report/audit_report.h"

namespace covmap::report {
namespace {

// Lower is worse. No default: a new verdict must be ranked here (-Werror=switch).
int verdict_rank(audit::SensorVerdict verdict) {
  switch (verdict) {
    case audit::SensorVerdict::kInconsistent: return 0;
    case audit::SensorVerdict::kModelMisfit: return 1;
    case audit::SensorVerdict::kNotInMap: return 2;
    case audit::SensorVerdict::kUnreported: return 3;
    case audit::SensorVerdict::kUndetermined: return 4;
    case audit::SensorVerdict::kConsistent: return 5;
  }
  throw std::logic_error("verdict_rank: a verdict outside the enumeration");
}

// Missing evidence sorts after any measured value; larger values first.
double evidence_key(const std::optional<double>& v) { return v && std::isfinite(*v) ? -*v : 0.0; }
bool has(const std::optional<double>& v) { return v && std::isfinite(*v); }

}  // namespace

bool needs_attention(audit::SensorVerdict verdict) { return verdict != audit::SensorVerdict::kConsistent; }

std::string_view basis_words(audit::VerdictBasis basis) {
  switch (basis) {
    case audit::VerdictBasis::kNone: return "";
    case audit::VerdictBasis::kBoundaryFit: return "the fit of its cell's boundaries";
    case audit::VerdictBasis::kCell: return "its cell in the map";
    case audit::VerdictBasis::kPrediction: return "the cell it would serve";
    case audit::VerdictBasis::kModelFit: return "the model fit around it";
  }
  throw std::logic_error("basis_words: a basis outside the enumeration");
}

std::vector<std::size_t> sensors_by_severity(std::span<const audit::SensorAudit> sensors) {
  std::vector<std::size_t> order(sensors.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto moved = [&](const audit::SensorAudit& s) {
    return s.reported && s.in_map ? std::optional<double>(s.position_error_m) : std::nullopt;
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    const audit::SensorAudit &a = sensors[i], &b = sensors[j];
    if (verdict_rank(a.verdict) != verdict_rank(b.verdict)) return verdict_rank(a.verdict) < verdict_rank(b.verdict);
    if (has(a.chi2) != has(b.chi2)) return has(a.chi2);
    if (evidence_key(a.chi2) != evidence_key(b.chi2)) return evidence_key(a.chi2) < evidence_key(b.chi2);
    if (has(moved(a)) != has(moved(b))) return has(moved(a));
    if (evidence_key(moved(a)) != evidence_key(moved(b))) return evidence_key(moved(a)) < evidence_key(moved(b));
    return a.id < b.id;
  });
  return order;
}

}  // namespace covmap::report
