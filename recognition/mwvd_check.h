// The two halves of recognize()'s MWVD check (paper 5, §5; the stage is mwvd_check.cpp). Internal
// to the recognition library.
//
// Is the input graph G the MWVD of the reconstructed sites S? Deciding it by matching G's nodes
// and arcs with the recomputed diagram D by position answers "no" wherever D's rounding moves an
// element by more than a fixed tolerance (far nodes of nearly tangent circles, degenerate nodes
// redrawn with another topology). Instead each element is judged against S at its own
// conditioning:
//   1. G against S (input_against_sites): every node of G is weighted-equidistant to the sites of
//      its faces, and sample points of every arc to the sites on its two sides, with no other site
//      closer; the residual of each test is allowed what the reconstruction's own uncertainty
//      (sites to τ·scale, weights to a relative τ, τ = RecognitionOptions::relative_tolerance)
//      and rounding can make of it at that point. This holds at every point of G iff each of G's
//      arcs is a piece of the MWVD's boundary between the right two regions.
//   2. D against G (recomputed_against_input): the MWVD may still have regions that G lacks
//      altogether (a missing orphan face). Every arc of D must have a counterpart in G — an arc
//      between the same two sites passing through the D-arc's midpoint — unless the arc is shorter
//      than what site errors of that size can move its end nodes by, or a third site is within the
//      allowance of being as close at its midpoint (then G may draw the node differently:
//      degenerate nodes, far nodes of nearly tangent circles, parallel bisectors of nearly
//      collinear sites meeting far away after rounding). A face of D none of
//      whose arcs has a counterpart is reported as a missing face, at a point of it.
// Together: G is the MWVD of S within the tolerance. Linear in the size of the graphs (nearest-site
// queries by a kd-tree, counterparts by a hash of site pairs). When the engine refuses to draw S
// (voronoi::EngineFailure) and G agrees with S at every point, the answer is "unknown", with the
// reason appended to the reconstruction's: a missing face cannot be ruled out, nor shown.
#pragma once

#include <span>
#include <vector>

#include "core/diagram.h"
#include "core/weighted_owner.h"
#include "recognition/compare.h"

namespace covmap::recognition::mwvd {

// The reconstructed sites on the two sides of an arc of G (kNone: outside the frame, unassigned).
struct ArcSites {
  int left = kNone;
  int right = kNone;
};

// Per arc of g: the sites of the traced faces on its sides (face_site: per face of g).
std::vector<ArcSites> arc_sites(const Diagram& g, const std::vector<int>& face_site);

// The size of the numbers that state an arc's curve, in the frame centred at `centre`, for its
// point p: a circle's centre and radius; a line's anchor and its lever to p.
double stated_size(const Arc& arc, Point centre, Point p);

// Allowance::spread of every site (labels: arc_sites; centre, scale: the input's extent).
std::vector<double> site_spreads(const Diagram& g, const std::vector<ArcSites>& labels, std::size_t sites, Point centre,
                                 double scale);

// What the reconstruction's uncertainty allows a difference of weighted distances to be.
struct Allowance {
  double tau = 0.0;    // relative: RecognitionOptions::relative_tolerance
  double scale = 0.0;  // the input's extent (a length)
  Point centre;        // the centre of the input's extent (its frame's origin)
  std::span<const Site> sites;
  // Per site, its uncertainty in units of τ·scale: the size, in extents and at least 1, of the
  // numbers that state its best-stated arc (in the input's frame; stated_curve reads them so). A
  // site whose only face is an orphan far out (nearly equal weights put one 180 extents away) is
  // fixed by that face's huge circles only to τ times their size; the recognition may then keep
  // it apart from its twin (two sites for one region, 4·10⁻¹⁰ apart at τ = 10⁻¹¹, rounded to 12
  // digits), whose bisector splits the twin's region in the recomputed diagram.
  std::vector<double> spread;
  double widest_spread = 1.0;

  // For |p − a|/w_a − |p − b|/w_b at p (da, db: those two distances; a, b: indices of sites): what
  // moving each site k by τ·spread_k·scale and changing its weight by a relative τ·spread_k can
  // change it by, plus the rounding of points whose coordinates (or curve) have the given
  // magnitude, plus moving p by `moved`.
  double residual(int a, double da, int b, double db, double magnitude, double moved = 0.0) const;
  // A bound of residual(a, da, k, dk, magnitude) − τ·spread_k·dk over all sites k no lighter than
  // lightest_weight.
  double residual_bound(int a, double da, double magnitude, double lightest_weight) const;

  // How far a point p of an input arc may lie from where the arc's numbers, exact, would put it:
  // each number is stated to τ of its own size in the input's frame (a rounded graph's are; the
  // recognition's arc-end allowance reads them the same way), so a huge circle of nearly equal
  // weights, rounded to d digits, is off its bisector by ~10⁻ᵈ·r although its end nodes are not.
  double stated_curve(const Arc& arc, Point p) const;
};

// The sites, for nearest-site queries (index: built over sites).
struct Sites {
  const std::vector<Site>& sites;
  const WeightedSiteIndex& index;
  double smallest_weight = 0.0;
};

std::vector<Difference> input_against_sites(const Diagram& g, const std::vector<ArcSites>& labels, const Sites& s,
                                            const Allowance& allowance);

std::vector<Difference> recomputed_against_input(const Diagram& recomputed, const Diagram& g,
                                                 const std::vector<ArcSites>& labels, const Sites& s,
                                                 const Allowance& allowance);

}  // namespace covmap::recognition::mwvd
