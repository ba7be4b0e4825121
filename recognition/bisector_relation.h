// Lemma 1 of seed paper 5: a generalized circle C is the bisector of sites s_i and s_j (for suitable
// weights) iff s_j is the inversion of s_i in C (the mirror image for a line). The weights then
// satisfy w_i / w_j = |c - s_i| / r = r / |c - s_j| for a circle with centre c and radius r, and
// are equal for a line.
#pragma once

#include "recognition/generalized_circle.h"
#include "voronoi/diagram.h"

namespace covmap::recognition {

struct WeightedPoint {
  Complex position;
  double weight = 1.0;
};

// The site on the other side of `bisector` from `site`. Its weight follows from Lemma 1; the site
// must not be the circle's centre (whose partner is at infinity).
WeightedPoint partner_across(const GeneralizedCircle& bisector, const WeightedPoint& site);

}  // namespace covmap::recognition
