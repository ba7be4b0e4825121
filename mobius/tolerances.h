// Every fixed approximate comparison of the Möbius machinery, in one place.
#pragma once

#include <cstddef>

namespace covmap::mobius::tolerance {

// Two solution circles whose intersection discriminant is negative by less than this fraction of
// the terms' size are taken as tangent (one common point): the discriminant of a true tangency
// comes out of rounding as ±1e-16 of them.
inline constexpr double kTangentDiscriminant = 1e-12;

// feasible_region: how many of the facets where the paraboloid leaves the lifted polyhedron are
// probed for a representative point. Each probe costs O(m); any one probe already yields a valid
// point, more only a deeper one.
inline constexpr std::size_t kMaxProbedFacets = 64;
// ... and the shortest step (a fraction of the search window's half-size) tried from a boundary
// point into the region: regions thinner than this are reported as having no interior.
inline constexpr double kSmallestProbeStep = 1e-9;
// ... and from how many of the deepest probe points a compass search climbs to the deepest point
// (the centre of the largest disk inside the region; the region need not be convex, so a few
// starts guard against a local summit). Each climb costs O(m) per step, ~30 halvings.
inline constexpr std::size_t kDeepestPointStarts = 4;
// A facet whose unit normal has a t-component below this fraction of its (x, y) part is vertical: it
// meets the paraboloid in a line (a line constraint or a side of the window; the normal of an
// exactly vertical facet, computed from its rounded vertices, is ~1e-17 off).
inline constexpr double kVerticalFacet = 1e-14;

}  // namespace covmap::mobius::tolerance
