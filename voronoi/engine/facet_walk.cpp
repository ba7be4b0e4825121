#include "voronoi/engine/facet_walk.h"

#include <algorithm>
#include <cmath>

namespace covmap::voronoi::engine {

Arc make_arc(int si, int sj, int from, int to, const std::vector<Site>& sites) {
  const Site& a = sites[si];
  const Site& b = sites[sj];
  Arc arc;
  arc.left_site = si;
  arc.right_site = sj;
  arc.from = from == kInfinityNode ? kNone : from;
  arc.to = to == kInfinityNode ? kNone : to;
  if (a.weight == b.weight) {
    // Walking counter-clockwise around c_j - c_i travels along rot90(s_j - s_i), i keeps left.
    arc.curve = Line{0.5 * (a.x + b.x), 0.5 * (a.y + b.y), -(b.y - a.y), b.x - a.x};
    arc.ccw = true;
  } else {
    // Centre as a correction to s_i with the difference of squares factored (NUMERICS.md).
    const double wi = a.weight, wj = b.weight;
    const double k = wi * wi / ((wi - wj) * (wi + wj));
    const double r = wi * wj * std::hypot(b.x - a.x, b.y - a.y) / std::fabs((wi - wj) * (wi + wj));
    arc.curve = Circle{a.x + k * (b.x - a.x), a.y + k * (b.y - a.y), r};
    // The walk projects counter-clockwise iff c_j - c_i points up, i.e. iff w_i < w_j; the disk
    // (the lighter site's side) is then on the left, which is site i either way.
    arc.ccw = wi < wj;
  }
  return arc;
}

namespace {

Node polish(long double px, long double py, const std::array<int, 3>& s,
            const std::vector<Site>& sites) {
  // In the frame of site o, node q satisfies for m = the two other sites
  //   F_m(q) = (w_m - w_o)(w_m + w_o)|q|² + 2 w_o² q·d_m - w_o² |d_m|² = 0,   d_m = s_m - s_o,
  // i.e. w_m²|q|² = w_o²|q - d_m|² expanded so that the nearly equal |q|² terms of nearly equal
  // weights cancel exactly instead of in rounding (nodes far from the sites sit on such arcs).
  const Site& o = sites[s[0]];
  const long double wo2 = (long double)o.weight * o.weight;
  long double dx[2], dy[2], dw2[2], dd[2];
  for (int m = 0; m < 2; ++m) {
    const Site& t = sites[s[m + 1]];
    dx[m] = (long double)t.x - o.x;
    dy[m] = (long double)t.y - o.y;
    dw2[m] = ((long double)t.weight - o.weight) * ((long double)t.weight + o.weight);
    dd[m] = dx[m] * dx[m] + dy[m] * dy[m];
  }
  auto residual = [&](long double x, long double y, long double f[2], long double jx[2],
                      long double jy[2]) {
    const long double q2 = x * x + y * y;
    for (int m = 0; m < 2; ++m) {
      f[m] = dw2[m] * q2 + 2 * wo2 * (x * dx[m] + y * dy[m]) - wo2 * dd[m];
      jx[m] = 2 * dw2[m] * x + 2 * wo2 * dx[m];
      jy[m] = 2 * dw2[m] * y + 2 * wo2 * dy[m];
    }
  };
  long double qx = px - o.x, qy = py - o.y;
  for (int it = 0; it < 12; ++it) {
    long double f[2], jx[2], jy[2];
    residual(qx, qy, f, jx, jy);
    const long double det = jx[0] * jy[1] - jx[1] * jy[0];
    if (det == 0 || !std::isfinite(static_cast<double>(det))) break;
    const long double sx = (f[0] * jy[1] - f[1] * jy[0]) / det;
    const long double sy = (jx[0] * f[1] - jx[1] * f[0]) / det;
    if (!std::isfinite(static_cast<double>(sx)) || !std::isfinite(static_cast<double>(sy))) break;
    // Backtracking: halve the step until the residual does not grow (a full Newton step can jump
    // towards the other intersection point when the circles are nearly tangent).
    const long double before = std::fabs(f[0]) + std::fabs(f[1]);
    long double scale = 1.0L;
    bool moved = false;
    for (int half = 0; half < 30; ++half, scale *= 0.5L) {
      long double f2[2], j2x[2], j2y[2];
      residual(qx - scale * sx, qy - scale * sy, f2, j2x, j2y);
      if (std::fabs(f2[0]) + std::fabs(f2[1]) <= before) {
        qx -= scale * sx;
        qy -= scale * sy;
        moved = scale * (std::fabs(sx) + std::fabs(sy)) > 0;
        break;
      }
    }
    if (!moved) break;
  }
  return Node{static_cast<double>(qx + o.x), static_cast<double>(qy + o.y)};
}

}  // namespace

Node root_node(std::array<long double, 4> a, std::array<long double, 4> b, int r, int roots,
               bool double_root, const std::array<int, 3>& tri, const std::vector<Site>& sites) {
  auto normalise = [](std::array<long double, 4>& v) {
    long double s = 0;
    for (auto x : v) s = std::max(s, std::fabs(x));
    if (s > 0)
      for (auto& x : v) x /= s;
  };
  normalise(a);
  normalise(b);
  auto g = [](const std::array<long double, 4>& p, const std::array<long double, 4>& q) {
    return 0.5L * (p[2] * q[3] + q[2] * p[3]) - p[0] * q[0] - p[1] * q[1];
  };
  const long double ga = g(a, a), gb = g(b, b), gab = g(a, b);
  // q(t) = ga (1-t)² + 2 gab t (1-t) + gb t² = qa t² + qb t + qc.
  const long double qa = ga - 2 * gab + gb, qb = 2 * (gab - ga), qc = ga;
  const long double disc = std::max(0.0L, qb * qb - 4 * qa * qc);
  long double t1, t2;
  if (qa == 0) {
    t1 = t2 = (qb != 0) ? -qc / qb : 0.5L;
  } else {
    const long double sq = std::sqrt(disc);
    const long double q = -0.5L * (qb + (qb >= 0 ? sq : -sq));
    t1 = q / qa;
    t2 = q != 0 ? qc / q : t1;
    if (t1 > t2) std::swap(t1, t2);
  }
  auto in01 = [](long double x) { return x >= 0 && x <= 1; };
  long double t;
  if (roots == 2) {
    t = r == 0 ? t1 : t2;
  } else if (double_root) {
    t = qa != 0 ? -qb / (2 * qa) : 0.5L * (t1 + t2);
  } else if (in01(t1) && in01(t2)) {
    // One root is an end of the edge (a vertex on the paraboloid); the crossing is the other.
    t = std::min(t1, 1 - t1) > std::min(t2, 1 - t2) ? t1 : t2;
  } else {
    t = in01(t1) ? t1 : t2;
  }
  t = std::clamp(t, 0.0L, 1.0L);
  // An end at infinity (w = 0) on the paraboloid's asymptotic cone is a root of q but no crossing.
  // When the crossing is at the other end, rounded to just outside [0, 1] (or to -0), the choice
  // above took the end at infinity and the node came out as 0/0 = NaN: the other root then (t1 <= t2,
  // so the one away from that end).
  if ((1 - t) * a[3] + t * b[3] == 0) t = std::clamp(t == 1 ? t1 : t2, 0.0L, 1.0L);
  std::array<long double, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = (1 - t) * a[k] + t * b[k];
  return polish(p[0] / p[3], p[1] / p[3], tri, sites);
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
