// CheckOptions validation, ViolationKind names and CheckReport summaries.
#include <array>
#include <cmath>
#include <string>

#include "check/check.h"
#include "check/check_internal.h"

namespace covmap::check {
namespace {

constexpr std::array<std::string_view, kViolationKindCount> kKindNames = {
    "BadIndex",           "BadSite",          "BadNode",          "BadCurve",
    "ArcEndNotOnCurve",   "LineArcReversed",  "FaceInconsistent", "NodeNotEquidistant",
    "NodeSiteCloser",     "ArcNotOnBisector", "ArcSiteCloser",    "ArcSidesSwapped",
    "BoundaryNotCovered", "ArcsCross",
};
static_assert(static_cast<std::size_t>(ViolationKind::ArcsCross) + 1 == kViolationKindCount);

bool fail(std::string* why, const char* text) {
  if (why != nullptr) *why = text;
  return false;
}

}  // namespace

bool CheckOptions::is_valid(std::string* why) const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (samples_per_arc < 1) return fail(why, "samples_per_arc must be at least 1");
  if (boundary_probes < 0) return fail(why, "boundary_probes must not be negative");
  if (!positive(relative_tolerance) || relative_tolerance >= 1.0)
    return fail(why, "relative_tolerance must be in (0, 1)");
  if (!positive(bisection_tolerance) || bisection_tolerance >= relative_tolerance)
    return fail(why, "bisection_tolerance must be positive and below relative_tolerance");
  if (!std::isfinite(rounding_ulps) || rounding_ulps < 0.0)
    return fail(why, "rounding_ulps must be finite and not negative");
  if (!positive(side_probe_factor) || side_probe_factor <= 1.0)
    return fail(why, "side_probe_factor must be greater than 1");
  if (!positive(coverage_factor) || coverage_factor < 1.0)
    return fail(why, "coverage_factor must be at least 1");
  if (!positive(probe_margin)) return fail(why, "probe_margin must be positive");
  if (max_reported < 0) return fail(why, "max_reported must not be negative");
  return true;
}

std::string_view to_string(ViolationKind kind) {
  return kKindNames[static_cast<std::size_t>(kind)];
}

bool violation_kind_from_string(std::string_view name, ViolationKind* kind) {
  for (std::size_t k = 0; k < kKindNames.size(); ++k) {
    if (kKindNames[k] == name) {
      *kind = static_cast<ViolationKind>(k);
      return true;
    }
  }
  return false;
}

std::size_t CheckReport::total_violations() const {
  std::size_t total = 0;
  for (const std::size_t n : counts_by_kind) total += n;
  return total;
}

std::size_t CheckReport::count(ViolationKind kind) const {
  return counts_by_kind[static_cast<std::size_t>(kind)];
}

std::string CheckReport::brief() const {
  using detail::strf;
  const std::string counts =
      strf("%zu nodes, %zu arc samples, %zu boundary points, %zu arc pairs; %.3f s", nodes_checked,
           arc_samples_checked, boundary_points_checked, crossings_tested, seconds);
  if (ok()) return "OK (" + counts + ")";
  std::string out = strf("%zu violations (", total_violations());
  bool first = true;
  for (std::size_t k = 0; k < kViolationKindCount; ++k) {
    if (counts_by_kind[k] == 0) continue;
    out +=
        strf("%s%s: %zu", first ? "" : ", ", std::string(kKindNames[k]).c_str(), counts_by_kind[k]);
    first = false;
  }
  out += "; " + counts + ")";
  if (!violations.empty()) {
    const Violation& v = violations.front();
    out += strf("; first: %s at (%.17g, %.17g): %s", std::string(to_string(v.kind)).c_str(), v.x,
                v.y, v.message.c_str());
    if (message_length_unit != 1.0) out += strf(" (lengths in units of %.17g)", message_length_unit);
  }
  return out;
}

}  // namespace covmap::check
