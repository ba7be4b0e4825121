#include "voronoi/engine/lifted_traits.h"

#include <algorithm>
#include <optional>

namespace covmap::voronoi::engine::lifted {
namespace {

template <class NT>
NT sub(const NT& a, const NT& b) {
  return a - b;
}

}  // namespace

// Semi-static filters for the two hot predicates. Entries are computed so that each has a small
// relative error: fl(x - x_t) (≤ u), fl(fl(w - w_t)·fl(w + w_t)) (≤ 3u), fl(dx² + dy²) (≤ 3u).
// A Laplace-expanded determinant of k columns then errs by at most c·u·Π_col max|entry|:
//   det3 (orientation): 6 terms, each ≤ (1+1+3)u entry + 2u products, 5u summation → c = 72;
//   det4 (power test): 24 terms, ≤ 8u entries + 3u products + 7u summation → c = 432.
// The constants below double those bounds. Tiny products (< 1e-280) skip the filter (underflow).
// The power filter evaluates det4 by 2×2 minors (det4_by_minors): each of the 24 terms passes
// through the entries (≤ 9u: dx, dy ≤ u each, dx²+dy² ≤ 4u from the rounded differences, dw² ≤
// 3u), one product and one difference per minor, one product of minors and ≤ 5 additions: ≤ 17u,
// within the 18u per term above, so the same constant bounds it. It is cheaper than Laplace
// (30 products instead of 40) and is evaluated for every conflict test of the triangulation.
namespace {
constexpr double kOrientationFilter = 2 * 72 * 0x1p-53;
constexpr double kPowerFilter = 2 * 432 * 0x1p-53;
constexpr double kFilterUnderflow = 1e-280;

double dw2(double w, double wt) { return (w - wt) * (w + wt); }
double absd(double x) { return x < 0 ? -x : x; }

// det m by the generalized Laplace expansion along columns 0, 1: Σ ± A_ij B_kl over the six row
// pairs, A_ij the 2×2 minor of columns 0, 1 in rows i, j and B_kl that of columns 2, 3 in the
// complementary rows.
double det4_by_minors(const double m[4][4]) {
  const auto a = [&](int i, int j) { return m[i][0] * m[j][1] - m[j][0] * m[i][1]; };
  const auto b = [&](int i, int j) { return m[i][2] * m[j][3] - m[j][2] * m[i][3]; };
  return a(0, 1) * b(2, 3) - a(0, 2) * b(1, 3) + a(0, 3) * b(1, 2) + a(1, 2) * b(0, 3) - a(1, 3) * b(0, 2) +
         a(2, 3) * b(0, 1);
}

std::optional<CGAL::Sign> static_sign(double det, double bound) {
  if (!(bound > kFilterUnderflow) || !(bound < 1e300)) return std::nullopt;
  if (det > bound) return CGAL::POSITIVE;
  if (det < -bound) return CGAL::NEGATIVE;
  return std::nullopt;
}
}  // namespace

// sign det[x_m - x_p, y_m - y_p, w_m² - w_p²], m = q, r, s (see header).
CGAL::Sign orientation(const RawPoint& p, const RawPoint& q, const RawPoint& r, const RawPoint& s) {
  {
    const RawPoint* rows[3] = {&q, &r, &s};
    double m[3][3];
    double mx[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
      m[i][0] = rows[i]->x() - p.x();
      m[i][1] = rows[i]->y() - p.y();
      m[i][2] = dw2(rows[i]->z(), p.z());
      for (int c = 0; c < 3; ++c) mx[c] = std::max(mx[c], absd(m[i][c]));
    }
    const double det = det3(m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1],
                            m[2][2]);
    if (auto sign = static_sign(det, kOrientationFilter * mx[0] * mx[1] * mx[2])) return *sign;
  }
  return filtered_sign([&](auto tag) {
    using NT = decltype(tag);
    Raw<NT> P(p), Q(q), R(r), S(s);
    return det3(Q.x - P.x, Q.y - P.y, Q.w2 - P.w2,  //
                R.x - P.x, R.y - P.y, R.w2 - P.w2,  //
                S.x - P.x, S.y - P.y, S.w2 - P.w2);
  });
}

// CGAL's coplanar_orientationC3 projects on xy, then yz, then xz. The projected 2D orientations of
// lifted points are, homogeneously, sign det[x,y,w²], -sign det[y,1,w²], -sign det[x,1,w²].
namespace {
template <class NT>
NT orient_xy(const Raw<NT>& p, const Raw<NT>& q, const Raw<NT>& r) {
  return det3(p.x, p.y, p.w2, q.x, q.y, q.w2, r.x, r.y, r.w2);
}
template <class NT>
NT orient_yz(const Raw<NT>& p, const Raw<NT>& q, const Raw<NT>& r) {
  const NT one(1);
  return -det3(p.y, one, p.w2, q.y, one, q.w2, r.y, one, r.w2);
}
template <class NT>
NT orient_xz(const Raw<NT>& p, const Raw<NT>& q, const Raw<NT>& r) {
  const NT one(1);
  return -det3(p.x, one, p.w2, q.x, one, q.w2, r.x, one, r.w2);
}
using Proj = int;  // 0: xy, 1: yz, 2: xz
template <class NT>
NT orient_proj(Proj k, const Raw<NT>& p, const Raw<NT>& q, const Raw<NT>& r) {
  return k == 0 ? orient_xy(p, q, r) : k == 1 ? orient_yz(p, q, r) : orient_xz(p, q, r);
}
CGAL::Sign proj_orientation(Proj k, const RawPoint& p, const RawPoint& q, const RawPoint& r) {
  return filtered_sign([&](auto tag) {
    using NT = decltype(tag);
    return orient_proj<NT>(k, Raw<NT>(p), Raw<NT>(q), Raw<NT>(r));
  });
}
}  // namespace

CGAL::Sign coplanar_orientation(const RawPoint& p, const RawPoint& q, const RawPoint& r) {
  for (Proj k : {0, 1}) {
    const CGAL::Sign o = proj_orientation(k, p, q, r);
    if (o != CGAL::ZERO) return o;
  }
  return proj_orientation(2, p, q, r);
}

CGAL::Sign coplanar_orientation(const RawPoint& p, const RawPoint& q, const RawPoint& r,
                                const RawPoint& s) {
  for (Proj k : {0, 1, 2}) {
    const CGAL::Sign o = proj_orientation(k, p, q, r);
    if (o != CGAL::ZERO || k == 2) return o * proj_orientation(k, p, q, s);
  }
  return CGAL::ZERO;
}

// Lifted X = x/w², Y = y/w², Z = -1/(2w²): compare by cross-multiplying the positive w².
CGAL::Comparison_result compare_xyz(const RawPoint& p, const RawPoint& q) {
  CGAL::Sign s = filtered_sign([&](auto tag) {
    using NT = decltype(tag);
    Raw<NT> P(p), Q(q);
    return P.x * Q.w2 - Q.x * P.w2;
  });
  if (s != CGAL::ZERO) return s;
  s = filtered_sign([&](auto tag) {
    using NT = decltype(tag);
    Raw<NT> P(p), Q(q);
    return P.y * Q.w2 - Q.y * P.w2;
  });
  if (s != CGAL::ZERO) return s;
  // Z_p < Z_q  <=>  w_p < w_q (weights are positive).
  return CGAL::compare(p.z(), q.z());
}

// sign det[dx, dy, dx²+dy², dw²], rows p, q, r, s minus t: the weighted in-circle test.
CGAL::Sign power_side(const RawPoint& p, const RawPoint& q, const RawPoint& r, const RawPoint& s,
                      const RawPoint& t) {
  {
    const RawPoint* rows[4] = {&p, &q, &r, &s};
    double m[4][4];
    double mx[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) {
      const double dx = rows[i]->x() - t.x(), dy = rows[i]->y() - t.y();
      m[i][0] = dx;
      m[i][1] = dy;
      m[i][2] = dx * dx + dy * dy;
      m[i][3] = dw2(rows[i]->z(), t.z());
      for (int c = 0; c < 4; ++c) mx[c] = std::max(mx[c], absd(m[i][c]));
    }
    if (auto sign = static_sign(det4_by_minors(m), kPowerFilter * mx[0] * mx[1] * mx[2] * mx[3])) return *sign;
  }
  return filtered_sign([&](auto tag) {
    using NT = decltype(tag);
    const Raw<NT> T(t);
    NT m[4][4];
    const RawPoint* rows[4] = {&p, &q, &r, &s};
    for (int i = 0; i < 4; ++i) {
      const Raw<NT> P(*rows[i]);
      const NT dx = P.x - T.x, dy = P.y - T.y;
      m[i][0] = dx;
      m[i][1] = dy;
      m[i][2] = dx * dx + dy * dy;
      m[i][3] = P.w2 - T.w2;
    }
    return det4(m);
  });
}

// Four coplanar lifted points (CGAL: power_side_of_oriented_power_sphereC3 with 4 points). For
// projection xy the power determinant is det[x, y, x²+y², w²] (rows p,q,r,t) and the orientation
// det[x, y, w²]; for xz and yz the coordinate column becomes a column of ones and both factors
// change sign together, so the product keeps the plain determinants.
CGAL::Sign power_side(const RawPoint& p, const RawPoint& q, const RawPoint& r, const RawPoint& t) {
  for (Proj k : {0, 2, 1}) {  // CGAL's order: xy, xz, yz
    const CGAL::Sign cmp = filtered_sign([&](auto tag) {
      using NT = decltype(tag);
      NT m[4][4];
      const RawPoint* rows[4] = {&p, &q, &r, &t};
      for (int i = 0; i < 4; ++i) {
        const Raw<NT> P(*rows[i]);
        m[i][0] = k == 1 ? P.y : P.x;
        m[i][1] = k == 0 ? P.y : NT(1);
        m[i][2] = P.r2;
        m[i][3] = P.w2;
      }
      return det4(m);
    });
    if (cmp != CGAL::ZERO || k == 1) {
      const CGAL::Sign o = filtered_sign([&](auto tag) {
        using NT = decltype(tag);
        const Raw<NT> P(p), Q(q), R(r);
        const NT one(1);
        if (k == 0) return orient_xy(P, Q, R);
        if (k == 1) return NT(det3(P.y, one, P.w2, Q.y, one, Q.w2, R.y, one, R.w2));
        return NT(det3(P.x, one, P.w2, Q.x, one, Q.w2, R.x, one, R.w2));
      });
      return cmp * o;
    }
  }
  return CGAL::ZERO;
}

// Three collinear lifted points: project on the first axis where p and q differ.
CGAL::Sign power_side(const RawPoint& p, const RawPoint& q, const RawPoint& t) {
  for (int k : {0, 1, 2}) {
    CGAL::Sign cmp;
    if (k == 2) {
      cmp = CGAL::compare(p.z(), q.z());
    } else {
      cmp = filtered_sign([&](auto tag) {
        using NT = decltype(tag);
        Raw<NT> P(p), Q(q);
        return k == 0 ? P.x * Q.w2 - Q.x * P.w2 : P.y * Q.w2 - Q.y * P.w2;
      });
    }
    if (cmp == CGAL::ZERO) continue;
    const CGAL::Sign d = filtered_sign([&](auto tag) {
      using NT = decltype(tag);
      const Raw<NT> P(p), Q(q), T(t);
      const NT one(1);
      if (k == 2) return NT(-det3(one, P.r2, P.w2, one, Q.r2, Q.w2, one, T.r2, T.w2));
      const NT& px = k == 0 ? P.x : P.y;
      const NT& qx = k == 0 ? Q.x : Q.y;
      const NT& tx = k == 0 ? T.x : T.y;
      return det3(px, P.r2, P.w2, qx, Q.r2, Q.w2, tx, T.r2, T.w2);
    });
    return cmp * d;
  }
  return CGAL::ZERO;
}

// Two lifted points: compare power weights ω_q and ω_p. With A = 4r² + 1 - 4w²r², ω = A/(4w⁴).
CGAL::Sign power_side(const RawPoint& p, const RawPoint& q) {
  return filtered_sign([&](auto tag) {
    using NT = decltype(tag);
    const Raw<NT> P(p), Q(q);
    const NT four(4), one(1);
    const NT ap = four * P.r2 + one - four * P.w2 * P.r2;
    const NT aq = four * Q.r2 + one - four * Q.w2 * Q.r2;
    return aq * P.w2 * P.w2 - ap * Q.w2 * Q.w2;
  });
}

bool span_space(std::span<const RawWeightedPoint> points) {
  const std::size_t n = points.size();
  if (n < 4) return false;
  const auto at = [&](std::size_t k) -> const RawPoint& { return points[k].point(); };
  // Distinct lifted points (build_diagram's sites are distinct): p0, p1 span a line; the first
  // point off it a plane (coplanar_orientation of three points is zero only when they are
  // collinear); then any point off that plane spans space.
  std::size_t k = 2;
  while (k < n && coplanar_orientation(at(0), at(1), at(k)) == CGAL::ZERO) ++k;
  if (k == n) return false;
  for (std::size_t m = 2; m < n; ++m)
    if (orientation(at(0), at(1), at(k), at(m)) != CGAL::ZERO) return true;
  return false;
}

}  // namespace covmap::voronoi::engine::lifted
