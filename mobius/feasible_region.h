// mobius::feasible_region — where can a point lie so that it is inside every one of a
// list of generalized disks? (seed paper 5, §3.2: the solution set ss(f) of a graph without
// constraining nodes is such an intersection of disks, disk complements and half-planes.)
//
// Method (the paper's, with the lifting map in place of its sphere inversion): lifting the plane
// to the paraboloid t = x² + y² turns every generalized circle A|z|² + 2Re(B̄z) + C = 0 into the
// plane A t + 2Re(B)x + 2Im(B)y + C = 0, and its inside into a half-space. The half-spaces (and a
// box bounding the search window) are intersected exactly with CGAL (halfspace_intersection_3
// over the exact-construction kernel); the feasible set is the part of the paraboloid inside that
// polyhedron. Every facet the paraboloid crosses carries an arc of the region's boundary; a point
// of each such arc, stepped into the region, is a candidate, and the candidate farthest from
// every constraint circle is the representative. O(m log m) for m constraints, plus O(k m) for the
// k ≤ kMaxProbedFacets probed facets.
//
// Contract: constraints are open regions {z : g.value(z) < 0}; degenerate forms (A = 0 and B = 0)
// are rejected with std::invalid_argument. The answer is restricted to the square window
// |x - cx|, |y - cy| ≤ half_size; a region that is empty there, or has no interior (circles
// touching at one point), is reported as empty. The representative is checked against every
// constraint directly in doubles; `margin` is its distance to the nearest constraint boundary.
#pragma once

#include <span>
#include <vector>

#include "mobius/generalized_circle.h"

namespace covmap::mobius {

struct FeasibleRegion {
  bool empty = true;
  Complex representative{0.0, 0.0};
  double margin = 0.0;     // distance from the representative to the region's boundary
  int facets_crossed = 0;  // facets of the lifted polyhedron the paraboloid meets (boundary arcs)
};

// Signed distance from z to the boundary of the region {g < 0}: positive inside.
double signed_distance_inside(const GeneralizedCircle& g, Complex z);

FeasibleRegion feasible_region(std::span<const GeneralizedCircle> constraints, Complex window_centre,
                               double half_size);

}  // namespace covmap::mobius
