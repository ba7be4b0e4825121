// check::check_diagram — an independent verifier for a Diagram.
//
// Contract. check_diagram reads a Diagram and tests it against the definition of the
// multiplicatively weighted Voronoi diagram (a point belongs to the site minimising |p - s| / w).
// It never calls an engine: every test is a closed form (the Apollonius circle or the perpendicular
// bisector of two sites) or a brute-force ownership query over all sites. That independence is its
// reason to exist.
//
// Accepted: any Diagram, however broken. Bad indices, non-finite numbers and non-positive weights
// are reported as violations (BadIndex, BadSite, ...) and the items concerned are left out of the
// geometric tests; nothing is thrown for a bad diagram. Invalid CheckOptions throw
// std::invalid_argument naming the field (CheckOptions::is_valid says why beforehand).
//
// What is tested (each item's violation kinds in brackets):
//   1. Structure: indices in range, finite geometry, positive weights [BadIndex, BadSite, BadNode,
//      BadCurve]; arc end nodes lie on the arc's own curve [ArcEndNotOnCurve]; a Line arc with two
//      finite ends runs along +d [LineArcReversed]; faces name valid arcs, sit on the side of each
//      half-arc that names their site, and form connected cycles [FaceInconsistent].
//   2. Nodes: weighted-equidistant from every site of their incident arcs [NodeNotEquidistant], and
//      no site at all is weighted-closer [NodeSiteCloser].
//   3. Arcs (frame arcs excepted): the curve is the bisector of the arc's two sites and sampled
//      points are on it [ArcNotOnBisector]; no third site is closer at a sample [ArcSiteCloser]; the site
//      named left is closer just left of the direction of travel [ArcSidesSwapped]. Frame arcs: no
//      site is closer than their inner site at a sample [ArcSiteCloser].
//   4. Coverage: random probe segments with different brute-force owners at their ends are bisected
//      to a boundary point of the true diagram, which must lie near an arc separating those two
//      owners (or near a node shared by both) [BoundaryNotCovered].
//   5. Planarity: no two arcs meet away from their end nodes [ArcsCross].
// With a clip polygon (Diagram::clip), samples and probes outside it are skipped.
//
// Tolerance. One length, eps = relative_tolerance * diagram_scale(d), decides every comparison; see
// CheckOptions::relative_tolerance (far from the origin it grows by the coordinates' own rounding,
// CheckOptions::rounding_ulps). Intersections of nearly tangent arcs are only reported when they
// lie farther from the end nodes than their own numerical uncertainty. "p is on the bisector of
// sites a and b" means the first-order distance from p to that bisector,
// |d_a - d_b| / |grad(d_a - d_b)| with d = |p - s| / w, is at most eps; "site k is closer" means p is more than eps inside
// k's side of the bisector of k and the claimed site. Distances are thus compared as lengths,
// whatever the weights.
//
// Range. Every finite diagram is checked: one whose extent, coordinates or weights lie near the ends
// of the double range (where squares overflow or weighted distances become infinite) is checked
// scaled by powers of two, which changes neither the MWVD nor any mantissa (see
// CheckReport::message_length_unit).
//
// Not guaranteed. The checks sample: a report without violations is strong evidence, not a proof.
// Crossings of unbounded arcs are only searched inside a box around the sites and nodes (one scale
// beyond it). Nearly tangent arcs meeting at a shared node can put their second intersection closer
// than the numerical noise to the node; such points count as "at the node".
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagram.h"

namespace covmap::check {

struct CheckOptions {
  // Interior sample points tested on every arc (unbounded arcs: on their stretch inside the region
  // box, see probe_margin). More samples catch shorter wrong stretches.
  int samples_per_arc = 16;
  // Boundary points of the true diagram to locate and look up (0 disables the coverage test).
  int boundary_probes = 4000;
  // Seed of the probe generator; the same seed gives the same probes and the same report.
  std::uint64_t seed = 1;

  // THE tolerance. eps = relative_tolerance * scale, where scale = diagram_scale(d) is the diagonal
  // of the bounding box of the sites. Used for: node equidistance, arc samples on the bisector, a
  // third site being closer, arc ends on their curve, curve parameters against the bisector's
  // closed form, and how far from end nodes an intersection must be to count as a crossing. 1e-7 is
  // what careful double-precision constructions reach on realistic data (see
  // docs/NUMERICS.md, 'Vertices far from the sites').
  double relative_tolerance = 1e-7;
  // Not a choice but a floating-point fact: a number of magnitude M is only known to about
  // M * DBL_EPSILON. Each test at a point p allows eps + rounding_ulps * DBL_EPSILON * M with
  // M = max(|p.x|, |p.y|) and, for tests against an arc's own curve, the magnitude of the numbers
  // stating that curve (|centre|, radius): a circle centred 5e9 away (weights equal to 11 digits)
  // cannot be written more precisely than ~1e-6 in any double-based format.
  double rounding_ulps = 64.0;
  // Probe bisection stops when the bracketing interval is shorter than this times scale. Must be
  // well below relative_tolerance so the located boundary point is exact for the test's purposes.
  double bisection_tolerance = 1e-12;
  // Side probes sit this many eps off the arc (capped at half a circle's radius): far enough that
  // an arc within eps of the bisector cannot put the probe on the wrong side.
  double side_probe_factor = 100.0;
  // A boundary point counts as covered when a matching arc (or a node of both owners) is within
  // coverage_factor * eps. Larger than 1 because an end node within eps of the true node can leave
  // a gap a few eps long where bisectors meet at a shallow angle.
  double coverage_factor = 10.0;
  // Not a tolerance: the probe box is the sites' bounding box grown by probe_margin * scale on
  // every side (the clip polygon's box when there is one), and unbounded arcs are sampled inside
  // the box of sites and nodes grown the same way.
  double probe_margin = 0.1;

  // At most this many violations are kept in the report; all are counted.
  int max_reported = 100;

  // True when every field is usable; otherwise false and, if why is given, the reason.
  bool is_valid(std::string* why) const;
};

enum class ViolationKind {
  BadIndex,            // an index out of range, or kNone where a value is required
  BadSite,             // non-finite position or weight, or weight <= 0
  BadNode,             // non-finite node position
  BadCurve,            // non-finite curve, radius <= 0, zero line direction
  ArcEndNotOnCurve,    // an end node is farther than eps from the arc's curve
  LineArcReversed,     // a finite Line arc runs against +d
  FaceInconsistent,    // a face boundary is not a cycle, or the face is on the wrong side of an arc
  NodeNotEquidistant,  // a node's sites are not weighted-equidistant from it
  NodeSiteCloser,      // some other site is weighted-closer to a node than its own sites
  ArcNotOnBisector,    // the curve or a sample is not on the bisector of the arc's sites
  ArcSiteCloser,       // at a sample of the arc some third site is weighted-closer
  ArcSidesSwapped,     // left_site is not the closer site just left of the arc
  BoundaryNotCovered,  // a boundary point of the true diagram has no arc near it
  ArcsCross,           // two arcs meet away from their end nodes
};
inline constexpr std::size_t kViolationKindCount = 14;

std::string_view to_string(ViolationKind kind);
// Inverse of to_string; false (and *kind untouched) for an unknown name.
bool violation_kind_from_string(std::string_view name, ViolationKind* kind);

struct Violation {
  ViolationKind kind = ViolationKind::BadIndex;
  std::string message;
  // Where it happened (a node, sample, probe or intersection point); NaN when there is no place.
  double x = 0.0;
  double y = 0.0;
  int node = kNone;
  int arc = kNone;
  int other_arc = kNone;  // ArcsCross: the second arc
  int site = kNone;       // the offending site (BadSite, the closer site, ...)
  int face = kNone;       // FaceInconsistent / face BadIndex
};

struct CheckReport {
  // The first CheckOptions::max_reported violations, in the order the checks ran.
  std::vector<Violation> violations;
  // Every violation found, by kind, including those not kept above.
  std::array<std::size_t, kViolationKindCount> counts_by_kind{};
  std::size_t nodes_checked = 0;
  std::size_t arc_samples_checked = 0;
  std::size_t boundary_points_checked = 0;
  std::size_t crossings_tested = 0;  // arc pairs whose boxes overlapped and were intersected
  double scale = 0.0;                // diagram_scale of the checked diagram
  double eps = 0.0;                  // the tolerance length actually used
  double seconds = 0.0;              // wall time of the check
  // Lengths inside violation messages are in this unit. It is 1 except for diagrams so large or so
  // small (beyond ~1e±30 in extent or coordinates) that they were checked scaled by a power of
  // two; positions (Violation::x, y), scale and eps are always in the diagram's own units.
  double message_length_unit = 1.0;

  std::size_t total_violations() const;
  std::size_t count(ViolationKind kind) const;
  bool ok() const { return total_violations() == 0; }
  // One line: "OK ..." with the counts, or the number of violations by kind and the first one.
  std::string brief() const;
};

// The length that relative tolerances multiply: the diagonal of the bounding box of the valid
// sites, or 1 when that is zero (fewer than two distinct sites).
double diagram_scale(const Diagram& d);

CheckReport check_diagram(const Diagram& d, const CheckOptions& options = {});

}  // namespace covmap::check
