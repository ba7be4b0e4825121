#include "voronoi/engine/facet_walk.h"

#include <algorithm>
#include <cmath>

namespace covmap::voronoi::engine {

Arc make_arc(int si, int sj, int from, int to, const RawPoint& pi, const RawPoint& pj) {
  const double xi = pi.x(), yi = pi.y(), wi = pi.z();
  const double xj = pj.x(), yj = pj.y(), wj = pj.z();
  Arc arc;
  arc.left_site = si;
  arc.right_site = sj;
  arc.from = from == kInfinityNode ? kNone : from;
  arc.to = to == kInfinityNode ? kNone : to;
  if (wi == wj) {
    // Walking counter-clockwise around c_j - c_i travels along rot90(s_j - s_i), i keeps left.
    arc.curve = Line{0.5 * (xi + xj), 0.5 * (yi + yj), -(yj - yi), xj - xi};
    arc.ccw = true;
  } else {
    // Centre as a correction to s_i with the difference of squares factored (docs/NUMERICS.md,
    // 'Apollonius centre').
    const double k = wi * wi / ((wi - wj) * (wi + wj));
    const double r = wi * wj * std::hypot(xj - xi, yj - yi) / std::fabs((wi - wj) * (wi + wj));
    arc.curve = Circle{xi + k * (xj - xi), yi + k * (yj - yi), r};
    // The walk projects counter-clockwise iff c_j - c_i points up, i.e. iff w_i < w_j; the disk
    // (the lighter site's side) is then on the left, which is site i either way.
    arc.ccw = wi < wj;
  }
  return arc;
}

bool circle_centre_in_facet(const RawPoint& pi, const RawPoint& pj,
                            const std::vector<RawPoint>& link) {
  for (const RawPoint& l : link) {
    const CGAL::Sign s = filtered_sign([&](auto tag) {
      using NT = decltype(tag);
      const SiteNT<NT> I(pi), J(pj), L(l);
      // Centre p0 = (w_i² s_j - w_j² s_i) / Δ with Δ = w_i² - w_j²; lifted onto the plane of
      // equal power to i and j. With E_m(P) = -2X x_m - 2Y y_m + Z + r_m², power(P, m) - |P|² =
      // E_m / w_m², so the test is w_i² E_l ≥ w_l² E_i, evaluated on P scaled by W = Δ² > 0.
      const NT delta = I.w2 - J.w2;
      const NT xn = I.w2 * J.x - J.w2 * I.x, yn = I.w2 * J.y - J.w2 * I.y;
      auto lh = [&](const SiteNT<NT>& m) {
        return NT(-2) * xn * m.x + NT(-2) * yn * m.y + m.r2 * delta;
      };
      const NT Z = -(I.w2 * lh(J) - J.w2 * lh(I));
      const NT W = delta * delta;
      auto e = [&](const SiteNT<NT>& m) {
        return NT(-2) * xn * delta * m.x + NT(-2) * yn * delta * m.y + Z + m.r2 * W;
      };
      return I.w2 * e(L) - L.w2 * e(I);
    });
    if (s == CGAL::NEGATIVE) return false;
  }
  return true;
}

}  // namespace covmap::voronoi::engine
