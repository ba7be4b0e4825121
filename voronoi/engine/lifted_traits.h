// Regular-triangulation traits in which a stored point (x, y, w) stands for the site's lifted
// weighted point.
//
// The MWVD is the vertical projection of the 3D power diagram of the points
//   c = (x/w², y/w², -1/(2w²)),  power weight ω = |c|² - (x²+y²)/w²,
// restricted to the paraboloid z = x² + y² (check: the power of (p, |p|²) is |p|² + |p-s|²/w² -
// |p|²·... up to terms common to all sites it equals |p - s|²/w²). Those coordinates are not
// representable in double, so rounding them would make CGAL triangulate slightly wrong points and
// break exactly the degenerate inputs covmap must handle (cocircular sites, equal weights). Instead
// the triangulation stores the raw site (x, y, w) in Point_3 and the site index in the weight slot,
// and every predicate is rewritten as a polynomial in the raw doubles. Multiplying the homogeneous
// lifted row u·(x, y, -1/2, x²+y², w²) (u = 1/w² > 0) through shows, e.g.
//   orientation_3(p,q,r,s)        = sign det[x_m - x_p, y_m - y_p, w_m² - w_p²]   (m = q, r, s)
//   power_side_of_oriented_power_sphere_3(p,q,r,s,t)
//                                  = sign det[dx, dy, dx² + dy², dw²]            (rows p..s minus t)
// which are evaluated filtered-exactly (exact_sign.h). The lower-dimensional predicates follow
// CGAL's own case analysis (kernel_ftC3.h) term by term, each determinant replaced by its
// homogeneous equivalent; tests/voronoi compare every predicate with CGAL's on exactly lifted
// rational coordinates.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <span>

#include "voronoi/engine/exact_sign.h"

namespace covmap::voronoi::engine {

using BaseKernel = CGAL::Epick;
using RawPoint = BaseKernel::Point_3;          // (x, y, w) of one site
using RawWeightedPoint = BaseKernel::Weighted_point_3;  // weight slot = site index

namespace lifted {

template <class NT>
struct Raw {
  NT x, y, w2, r2;  // w² and x² + y², exact in NT
  explicit Raw(const RawPoint& p) : x(p.x()), y(p.y()), w2(NT(p.z()) * NT(p.z())), r2(x * x + y * y) {}
};

CGAL::Sign orientation(const RawPoint& p, const RawPoint& q, const RawPoint& r, const RawPoint& s);
CGAL::Sign coplanar_orientation(const RawPoint& p, const RawPoint& q, const RawPoint& r);
CGAL::Sign coplanar_orientation(const RawPoint& p, const RawPoint& q, const RawPoint& r,
                                const RawPoint& s);
CGAL::Comparison_result compare_xyz(const RawPoint& p, const RawPoint& q);
CGAL::Sign power_side(const RawPoint& p, const RawPoint& q, const RawPoint& r, const RawPoint& s,
                      const RawPoint& t);
CGAL::Sign power_side(const RawPoint& p, const RawPoint& q, const RawPoint& r, const RawPoint& t);
CGAL::Sign power_side(const RawPoint& p, const RawPoint& q, const RawPoint& t);
CGAL::Sign power_side(const RawPoint& p, const RawPoint& q);

// Whether some four of the lifted points are not coplanar (exact): then their regular
// triangulation has dimension 3, since no lifted site is hidden.
bool span_space(std::span<const RawWeightedPoint> points);

}  // namespace lifted

// The traits: Epick's types, with every predicate the triangulation calls replaced.
struct LiftedTraits : public BaseKernel {
  struct Orientation_3 {
    using result_type = CGAL::Orientation;
    CGAL::Orientation operator()(const RawPoint& p, const RawPoint& q, const RawPoint& r,
                                 const RawPoint& s) const {
      return lifted::orientation(p, q, r, s);
    }
  };
  struct Coplanar_orientation_3 {
    using result_type = CGAL::Orientation;
    CGAL::Orientation operator()(const RawPoint& p, const RawPoint& q, const RawPoint& r) const {
      return lifted::coplanar_orientation(p, q, r);
    }
    CGAL::Orientation operator()(const RawPoint& p, const RawPoint& q, const RawPoint& r,
                                 const RawPoint& s) const {
      return lifted::coplanar_orientation(p, q, r, s);
    }
  };
  struct Compare_xyz_3 {
    using result_type = CGAL::Comparison_result;
    CGAL::Comparison_result operator()(const RawPoint& p, const RawPoint& q) const {
      return lifted::compare_xyz(p, q);
    }
  };
  struct Equal_3 {
    using result_type = bool;
    bool operator()(const RawPoint& p, const RawPoint& q) const { return p == q; }
  };
  struct Power_side_of_oriented_power_sphere_3 {
    using result_type = CGAL::Oriented_side;
    using WP = RawWeightedPoint;
    CGAL::Oriented_side operator()(const WP& p, const WP& q, const WP& r, const WP& s,
                                   const WP& t) const {
      return lifted::power_side(p.point(), q.point(), r.point(), s.point(), t.point());
    }
    CGAL::Oriented_side operator()(const WP& p, const WP& q, const WP& r, const WP& t) const {
      return lifted::power_side(p.point(), q.point(), r.point(), t.point());
    }
    CGAL::Oriented_side operator()(const WP& p, const WP& q, const WP& t) const {
      return lifted::power_side(p.point(), q.point(), t.point());
    }
    CGAL::Oriented_side operator()(const WP& p, const WP& q) const {
      return lifted::power_side(p.point(), q.point());
    }
  };
  // Used only by queries covmap never makes (Gabriel tests, nearest power vertex); poisoned so a
  // future call cannot silently use Epick's meaning of the coordinates.
  struct Unsupported {
    template <class... A>
    CGAL::Oriented_side operator()(const A&...) const {
      static_assert(sizeof...(A) == 0, "not available on lifted covmap points");
      return CGAL::ON_ORIENTED_BOUNDARY;
    }
  };
  using Power_side_of_bounded_power_sphere_3 = Unsupported;
  using Compare_power_distance_3 = Unsupported;

  Orientation_3 orientation_3_object() const { return {}; }
  Coplanar_orientation_3 coplanar_orientation_3_object() const { return {}; }
  Compare_xyz_3 compare_xyz_3_object() const { return {}; }
  Equal_3 equal_3_object() const { return {}; }
  Power_side_of_oriented_power_sphere_3 power_side_of_oriented_power_sphere_3_object() const {
    return {};
  }
  Power_side_of_bounded_power_sphere_3 power_side_of_bounded_power_sphere_3_object() const {
    return {};
  }
  Compare_power_distance_3 compare_power_distance_3_object() const { return {}; }
};

}  // namespace covmap::voronoi::engine
