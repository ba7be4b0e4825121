// The nodes of three sites, constructed from the sites alone.
//
// Three sites o = s[0], m₁ = s[1], m₂ = s[2] with d_m = s_m − s_o and Δw_m² = w_m² − w_o² are
// weighted-equidistant at q = s_o + p exactly when, for m = m₁, m₂,
//     F_m(p) = Δw_m² |p|² + 2 w_o² p·d_m − w_o² |d_m|² = 0.
// Eliminating |p|² leaves the line p·n = h/2 with n = Δw₂² d₁ − Δw₁² d₂ and
// h = Δw₂² |d₁|² − Δw₁² |d₂|²: the projection of the three sites' power line. Writing
// p = (h n + T perp(n)) / (2|n|²), perp(x, y) = (−y, x), turns F_m into the quadratic
//     a T² + 2 B T + C = 0,   a = Δw_m²,  B = 2 w_o² perp(n)·d_m,
//     C = a h² + 4 w_o² (h n·d_m − |d_m|² |n|²),
// whose two roots are the two nodes, ordered along perp(n). m is the site whose Δw_m² is larger in
// magnitude (the other may be 0: a line bisector). If all three weights are equal, n = 0 and the
// one finite node is the circumcentre.
//
// Every coefficient is a polynomial in the input doubles, so it is evaluated with a running error
// bound and, when the node's error that bound implies exceeds tolerance::kNodeError of the sites'
// extent (nearly tangent bisectors make the discriminant B² − aC cancel; nearly collinear lifted
// sites make n cancel; far nodes magnify everything), exactly; the node is then computed from
// coefficients each rounded once. Nothing depends on rounded power vertices far
// away, which is what made nodes of nearly collinear sites land hundreds of units off their
// curves. Which of the two roots is wanted is decided by the caller from exact signs.
#pragma once

#include <array>

#include "core/diagram.h"
#include "voronoi/engine/edge_pattern.h"

namespace covmap::voronoi::engine {

// Which root of the quadratic: the one met first or second when travelling along +perp(n).
enum class AlongLine { kFirst, kSecond };

// The root of pattern `p` wanted at interior index r, for an edge travelled in direction
// σ·perp(n) (σ = ±1): the paraboloid's inside is the segment between the two roots, so an edge
// entering it (sign − then +) meets the first root of its travel and one leaving it the second.
AlongLine wanted_root(const EdgePattern& p, int r, int sigma);

// The sign σ with which travelling from power vertex `a` to `b` across the facet `tri` follows
// perp(n): `away` is the fourth site of the finite cell whose vertex the travel leaves (pass
// `leaving_finite` = false when it is the fourth site of the finite cell the travel reaches).
int travel_sign(const std::array<RawPoint, 3>& tri, const RawPoint& away, bool leaving_finite);

// The same for the planar extractor, whose power lines are travelled along the lifted normal.
int travel_sign_planar(const std::array<RawPoint, 3>& tri);

// Two triples whose power lines are one line (coplanar and co-circular lifted sites: the caller
// has checked this exactly) cross the paraboloid in the same two points; whether root `wa` of `a`
// and root `wb` of `b` are one point. Each triple orders its roots along its own perp(n), so this
// is the exact sign of n_a·n_b, unless the line is tangent (both roots one point) or a triple has
// equal weights (its one node, the circumcentre). Nodes of the two roots of one line can be closer
// than any rounding (internally tangent bisector circles moved by an ulp), so proximity alone
// must never pair them.
bool same_root(const std::array<RawPoint, 3>& a, AlongLine wa, const std::array<RawPoint, 3>& b, AlongLine wb);

// The node of `tri` at root `which` (in the coordinates of `tri`, whose bounding-box diagonal is
// `extent`). `exact` (optional) is set when the coefficients needed the exact stage.
Node triple_node(const std::array<RawPoint, 3>& tri, AlongLine which, double extent, bool* exact = nullptr);

}  // namespace covmap::voronoi::engine
