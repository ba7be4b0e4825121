// Filtered exact sign evaluation for polynomial predicates on double input.
//
// A predicate is written once as a generic lambda over a number type NT and evaluated in up to
// three stages, each only if the previous one cannot certify the sign:
//  1. Approx: plain doubles with a running error bound (Higham, Accuracy and Stability of
//     Numerical Algorithms, §3.3). Each value v carries e ≥ |v - exact|: an input double has
//     e = 0; fl(x ± y) adds u'|v|; fl(x·y) has e = |x|e_y + |y|e_x + e_x e_y + u'|v|. We use
//     u' = kApproxUnitRoundoff = 2⁻⁵² (twice the unit roundoff, which also absorbs the rounding
//     of the bound's own arithmetic) plus kApproxUnderflowSlack per operation, which covers the
//     absolute error of a result in the subnormal range. The sign is certain when |v| > e.
//  2. Interval: CGAL::Interval_nt with protected rounding, which encloses the true value.
//  3. Exact: CGAL::Mpzf, exact for +, -, ×. The predicates are polynomials in the input doubles
//     (no division), so this stage is exact and the returned sign is always the true sign.
#pragma once

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>

#include <optional>

namespace covmap::voronoi::engine {

using Interval = CGAL::Interval_nt<false>;
using Exact = CGAL::Mpzf;

inline constexpr double kApproxUnitRoundoff = 0x1p-52;      // see the header comment, stage 1
inline constexpr double kApproxUnderflowSlack = 0x1p-1000;   // ≫ the 2⁻¹⁰⁷⁴ subnormal spacing

// A double with a bound on its absolute error (stage 1).
struct Approx {
  double v = 0.0;
  double e = 0.0;
  Approx() = default;
  Approx(double x) : v(x), e(0.0) {}  // NOLINT: implicit like a number type; inputs are exact
  Approx(double value, double error) : v(value), e(error) {}
};
inline double approx_abs(double x) { return x < 0 ? -x : x; }
inline Approx operator+(const Approx& x, const Approx& y) {
  const double v = x.v + y.v;
  return {v, x.e + y.e + kApproxUnitRoundoff * approx_abs(v) + kApproxUnderflowSlack};
}
inline Approx operator-(const Approx& x, const Approx& y) {
  const double v = x.v - y.v;
  return {v, x.e + y.e + kApproxUnitRoundoff * approx_abs(v) + kApproxUnderflowSlack};
}
inline Approx operator*(const Approx& x, const Approx& y) {
  const double v = x.v * y.v;
  return {v, approx_abs(x.v) * y.e + approx_abs(y.v) * x.e + x.e * y.e +
                 kApproxUnitRoundoff * approx_abs(v) + kApproxUnderflowSlack};
}
inline Approx operator-(const Approx& x) { return {-x.v, x.e}; }

inline std::optional<CGAL::Sign> certain_sign(const Approx& x) {
  if (!(x.e < 1e300) || !(approx_abs(x.v) < 1e300)) return std::nullopt;  // overflow or NaN
  if (x.v > x.e) return CGAL::POSITIVE;
  if (x.v < -x.e) return CGAL::NEGATIVE;
  return std::nullopt;
}
inline double approx_value(const Approx& x) { return x.v; }
inline double approx_value(const Interval& x) { return CGAL::to_double(x); }
inline double approx_value(const CGAL::Mpzf& x) { return CGAL::to_double(x); }

// Sign of a value of either number type; nullopt when an interval contains zero and other values.
inline std::optional<CGAL::Sign> certain_sign(const Interval& v) {
  const CGAL::Uncertain<CGAL::Sign> s = CGAL::sign(v);
  if (!CGAL::is_certain(s)) return std::nullopt;
  return CGAL::get_certain(s);
}
inline std::optional<CGAL::Sign> certain_sign(const Exact& v) { return CGAL::sign(v); }

// f(NT{}) must return an NT whose sign is wanted.
template <class F>
CGAL::Sign filtered_sign(F&& f) {
  if (auto s = certain_sign(f(Approx{}))) return *s;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    if (auto s = certain_sign(f(Interval{}))) return *s;
  }
  return CGAL::sign(f(Exact{}));
}

template <class NT>
NT det2(const NT& a, const NT& b, const NT& c, const NT& d) {
  return a * d - b * c;
}

template <class NT>
NT det3(const NT& a, const NT& b, const NT& c,  //
        const NT& d, const NT& e, const NT& f,  //
        const NT& g, const NT& h, const NT& i) {
  return a * det2(e, f, h, i) - b * det2(d, f, g, i) + c * det2(d, e, g, h);
}

template <class NT>
NT det4(const NT m[4][4]) {
  // Laplace expansion along the first row; exact types make the order irrelevant.
  NT r(0);
  for (int c = 0; c < 4; ++c) {
    NT sub[3][3];
    for (int i = 1; i < 4; ++i)
      for (int j = 0, k = 0; j < 4; ++j)
        if (j != c) sub[i - 1][k++] = m[i][j];
    NT minor = det3(sub[0][0], sub[0][1], sub[0][2], sub[1][0], sub[1][1], sub[1][2], sub[2][0],
                    sub[2][1], sub[2][2]);
    if (c % 2 == 0)
      r = r + m[0][c] * minor;
    else
      r = r - m[0][c] * minor;
  }
  return r;
}

}  // namespace covmap::voronoi::engine
