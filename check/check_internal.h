// Shared state of one check_diagram run, and the passes that read it. Internal to the checker.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "check/arc_geometry.h"
#include "check/check.h"
#include "core/weighted_owner.h"

namespace covmap::check::detail {

struct CheckContext {
  CheckContext(const Diagram& diagram, const CheckOptions& opts, CheckReport& out);

  const Diagram& d;
  const CheckOptions& options;
  CheckReport& report;
  double scale;  // diagram_scale(d)
  double eps;    // options.relative_tolerance * scale: the one tolerance length
  WeightedSiteIndex owners;

  // Filled by check_structure; later passes only look at items marked usable.
  std::vector<char> site_ok;
  std::vector<char> node_ok;
  std::vector<std::optional<ArcPath>> paths;  // set for arcs whose geometry can be tested
  std::vector<std::vector<int>> node_sites;   // distinct sites of the arcs at each node
  Box region;  // sites, nodes and clip polygon, grown by probe_margin * scale

  // The tolerance for a comparison whose numbers have magnitude up to `magnitude`: eps plus their
  // rounding (CheckOptions::rounding_ulps).
  double tol(double magnitude) const { return eps + rounding(magnitude); }
  // The rounding alone of numbers of magnitude up to `magnitude`.
  double rounding(double magnitude) const {
    return options.rounding_ulps * std::numeric_limits<double>::epsilon() * magnitude;
  }
  static double magnitude(Point p) { return std::max(std::abs(p.x), std::abs(p.y)); }
  // for_each_closer bounds are raised by this relative amount so that a site whose weighted
  // distance merely rounds to the claimed one is still examined (bisector_offset, computed more
  // carefully, then decides). A guard for rounding, not a tolerance.
  static double closer_bound(double d) {
    return d * (1.0 + 8.0 * std::numeric_limits<double>::epsilon());
  }

  bool in_clip(Point p) const { return d.clip.empty() || point_in_polygon(p, d.clip); }
  void add(ViolationKind kind, Point where, std::string message, Violation ids = {});
};

// The magnitude of the numbers that state an arc's curve: a circle centred 5e9 away is only known
// to ~1e-6 however it was computed, so points on it are tested with that rounding allowed for
// (CheckOptions::rounding_ulps), never with a looser relative tolerance.
inline double representation_magnitude(const ArcPath& path) {
  if (!path.circle) return std::max(std::abs(path.origin.x), std::abs(path.origin.y));
  return std::max({std::abs(path.centre.x), std::abs(path.centre.y), path.radius});
}

// printf-style formatting for messages.
std::string strf(const char* format, ...) __attribute__((format(printf, 1, 2)));

void check_structure(CheckContext& c);
void check_nodes(CheckContext& c);
void check_arcs(CheckContext& c);
void check_coverage(CheckContext& c);
void check_crossings(CheckContext& c);

}  // namespace covmap::check::detail
