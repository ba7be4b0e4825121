// Lemma 1 of seed paper 5: a generalized circle C is the bisector of sites s_i and s_j (for suitable
// weights) iff s_j is the inversion of s_i in C (the mirror image for a line). The weights then
// satisfy w_i / w_j = |c - s_i| / r = r / |c - s_j| for a circle with centre c and radius r, and
// are equal for a line.
#pragma once

#include <vector>

#include "mobius/generalized_circle.h"
#include "core/diagram.h"

namespace covmap::mobius {

struct WeightedPoint {
  Complex position;
  double weight = 1.0;
};

// The site on the other side of `bisector` from `site`. Its weight follows from Lemma 1; the site
// must not be the circle's centre (whose partner is at infinity).
WeightedPoint partner_across(const GeneralizedCircle& bisector, const WeightedPoint& site);

// The same relation for a graph's arc, evaluated relative to a point v on it (a node of the arc,
// or for a full circle its rightmost point). With γ = c - v (|γ| = r), the partner of p = v + δ is
//   v + γ·conj(δ) / conj(δ - γ),   weight w·|γ| / |γ - δ|,
// and p is inside the disk iff |δ|² < 2 Re(conj(γ) δ). In plane coordinates, the inversion
// c + r²/conj(p - c) in a huge circle (nearly equal weights, r ≫ |δ|) cancels terms of size r to
// leave a point at distance ~|δ|: each crossing of such an arc would cost log10(r/|δ|) digits,
// and breadth-first propagation crosses thousands. Here no term exceeds the result's own size
// except in the ratio γ / conj(δ - γ), which is accurate to a few ulps whatever r is. Lines are
// mirrors through their anchor point.
struct ArcBisector {
  bool line = false;
  Complex v;      // a point on the arc
  Complex gamma;  // circles: centre - v; lines: unit direction of travel
};

// Anchored at the arc's first node (its end node for a ray).
ArcBisector arc_bisector(const Arc& arc, const std::vector<Node>& nodes);

// Anchored at whichever of the arc's nodes — and for a line, its own stated point — lies nearest
// `near` (the site to be mirrored). The relation's error is a few ulps of |p - v|: a node far from
// the site costs digits in proportion. Parallel bisectors of nearly collinear equal-weight sites
// meet ~1e15 extents out, and a mirror anchored at that node was off by 0.1 extents.
ArcBisector arc_bisector(const Arc& arc, const std::vector<Node>& nodes, Complex near);

WeightedPoint partner_across(const ArcBisector& bisector, const WeightedPoint& site);

// True when p lies strictly inside the disk of a circle arc, or strictly left of a line arc's
// direction of travel.
bool strictly_inside(const ArcBisector& bisector, Complex p);

}  // namespace covmap::mobius
