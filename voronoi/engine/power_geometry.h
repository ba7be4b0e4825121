// Homogeneous power-diagram geometry of lifted sites, as polynomials in the raw site doubles.
//
// A site s = (x, y) with weight w lifts to c = (x, y, -1/2)/w². A point P = (X, Y, Z) of lifted
// space has equal power to sites m of a set iff, for each m,
//     -2 X x_m - 2 Y y_m + Z + (x_m² + y_m²) + κ w_m² = 0
// for one common κ. Subtracting the equation of a reference site o removes Z, leaving rows
//     [-2(x_m-x_o), -2(y_m-y_o), w_m²-w_o²] · (X, Y, κ) = -(r_m² - r_o²),
// and Z = 2 x_o X + 2 y_o Y - r_o² - κ w_o². Points are kept homogeneous (X, Y, Z, W), W ≥ 0,
// W = 0 for directions. The paraboloid z = x²+y² becomes g(P) = Z W - X² - Y² = 0; the inside
// (g > 0) projects onto the points closer to these sites than the power diagram boundary says.
// Everything here is written over a number type NT (Interval or Mpzf, see exact_sign.h).
#pragma once

#include <array>
#include <optional>

#include "voronoi/engine/exact_sign.h"
#include "voronoi/engine/lifted_traits.h"

namespace covmap::voronoi::engine {

template <class NT>
struct Homog {
  NT X, Y, Z, W;
};

template <class NT>
Homog<NT> negated(const Homog<NT>& a) {
  return Homog<NT>{-a.X, -a.Y, -a.Z, a.W};
}

template <class NT>
struct SiteNT {
  NT x, y, w2, r2;
  explicit SiteNT(const RawPoint& p)
      : x(p.x()), y(p.y()), w2(NT(p.z()) * NT(p.z())), r2(x * x + y * y) {}
};

template <class NT>
struct Row {
  NT a, b, c, rhs;  // a X + b Y + c κ = rhs
};

template <class NT>
Row<NT> equal_power_row(const SiteNT<NT>& o, const SiteNT<NT>& m) {
  return {NT(-2) * (m.x - o.x), NT(-2) * (m.y - o.y), m.w2 - o.w2, o.r2 - m.r2};
}

// Z W in terms of the (X, Y, κ) solution scaled by W.
template <class NT>
NT z_times_w(const SiteNT<NT>& o, const NT& X, const NT& Y, const NT& K, const NT& W) {
  return NT(2) * o.x * X + NT(2) * o.y * Y - o.r2 * W - o.w2 * K;
}

// The point satisfying three linear rows in (X, Y, κ), lifted with the Z of reference site o.
// nullopt if the system's determinant is uncertain (intervals) or zero.
template <class NT>
std::optional<Homog<NT>> solve_rows(const SiteNT<NT>& o, const Row<NT> (&r)[3]) {
  NT D = det3(r[0].a, r[0].b, r[0].c, r[1].a, r[1].b, r[1].c, r[2].a, r[2].b, r[2].c);
  NT DX = det3(r[0].rhs, r[0].b, r[0].c, r[1].rhs, r[1].b, r[1].c, r[2].rhs, r[2].b, r[2].c);
  NT DY = det3(r[0].a, r[0].rhs, r[0].c, r[1].a, r[1].rhs, r[1].c, r[2].a, r[2].rhs, r[2].c);
  NT DK = det3(r[0].a, r[0].b, r[0].rhs, r[1].a, r[1].b, r[1].rhs, r[2].a, r[2].b, r[2].rhs);
  const auto sd = certain_sign(D);
  if (!sd || *sd == CGAL::ZERO) return std::nullopt;
  if (*sd == CGAL::NEGATIVE) {
    D = -D, DX = -DX, DY = -DY, DK = -DK;
  }
  return Homog<NT>{DX, DY, z_times_w(o, DX, DY, DK, D), D};
}

// The power vertex of four sites (a finite cell). A real cell is never flat, so nullopt only
// means "uncertain in intervals".
template <class NT>
std::optional<Homog<NT>> power_vertex(const std::array<RawPoint, 4>& s) {
  const SiteNT<NT> o(s[0]);
  const Row<NT> r[3] = {equal_power_row(o, SiteNT<NT>(s[1])), equal_power_row(o, SiteNT<NT>(s[2])),
                        equal_power_row(o, SiteNT<NT>(s[3]))};
  return solve_rows(o, r);
}

// The normal (c_1 - c_0) × (c_2 - c_0) of three lifted sites, scaled by w_0² w_1² w_2² > 0.
template <class NT>
Homog<NT> lifted_normal(const std::array<RawPoint, 3>& s) {
  NT v[3][3];
  NT w2[3];
  for (int k = 0; k < 3; ++k) {
    v[k][0] = NT(s[k].x());
    v[k][1] = NT(s[k].y());
    v[k][2] = NT(-0.5);
    w2[k] = NT(s[k].z()) * NT(s[k].z());
  }
  auto cross = [&](int a, int b, int c) {  // w_c² (s̃_a × s̃_b)
    return std::array<NT, 3>{w2[c] * (v[a][1] * v[b][2] - v[a][2] * v[b][1]),
                             w2[c] * (v[a][2] * v[b][0] - v[a][0] * v[b][2]),
                             w2[c] * (v[a][0] * v[b][1] - v[a][1] * v[b][0])};
  };
  const auto a = cross(0, 1, 2), b = cross(1, 2, 0), c = cross(2, 0, 1);
  return Homog<NT>{a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2], NT(0)};
}

// c_j - c_i scaled by w_i² w_j² > 0, as a direction.
template <class NT>
Homog<NT> lifted_difference(const RawPoint& i, const RawPoint& j) {
  const SiteNT<NT> I(i), J(j);
  return Homog<NT>{I.w2 * J.x - J.w2 * I.x, I.w2 * J.y - J.w2 * I.y, NT(-0.5) * (I.w2 - J.w2),
                   NT(0)};
}

template <class NT>
Homog<NT> cross(const Homog<NT>& a, const Homog<NT>& b) {
  return Homog<NT>{a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X, NT(0)};
}

// The point of the power line of three coplanar lifted sites that lies in their plane (normal n).
template <class NT>
std::optional<Homog<NT>> planar_power_centre(const std::array<RawPoint, 3>& s, const Homog<NT>& n) {
  const SiteNT<NT> o(s[0]);
  const NT two(2);
  Row<NT> r[3] = {equal_power_row(o, SiteNT<NT>(s[1])), equal_power_row(o, SiteNT<NT>(s[2])), {}};
  // n·P = n·c_o with Z = 2x_o X + 2y_o Y - r_o² - κ w_o², multiplied through by w_o².
  r[2].a = o.w2 * (n.X + two * o.x * n.Z);
  r[2].b = o.w2 * (n.Y + two * o.y * n.Z);
  r[2].c = -o.w2 * o.w2 * n.Z;
  r[2].rhs = o.w2 * n.Z * o.r2 + (n.X * o.x + n.Y * o.y - NT(0.5) * n.Z);
  return solve_rows(o, r);
}

// The direction of the power line of three sites, unoriented. Its (X, Y) part is 2·perp(n) with
// n = Δw₂² d₁ − Δw₁² d₂ (d_m = s_m − s_0, Δw_m² = w_m² − w_0²) and perp(x, y) = (−y, x): the
// normal of the line's projection used by engine/triple_node.h.
template <class NT>
Homog<NT> power_line_direction(const std::array<RawPoint, 3>& s) {
  const SiteNT<NT> o(s[0]);
  const Row<NT> p = equal_power_row(o, SiteNT<NT>(s[1]));
  const Row<NT> q = equal_power_row(o, SiteNT<NT>(s[2]));
  // Null vector of the two homogeneous rows: their cross product in (X, Y, κ).
  const NT dX = p.b * q.c - p.c * q.b;
  const NT dY = p.c * q.a - p.a * q.c;
  const NT dK = p.a * q.b - p.b * q.a;
  return Homog<NT>{dX, dY, NT(2) * o.x * dX + NT(2) * o.y * dY - o.w2 * dK, NT(0)};
}

// Positive when the power of site `away` grows more slowly than that of s[0] along d (a direction
// along the power line of s), i.e. d·(c_away − c_0) > 0 for the lifted sites, multiplied by
// w_0² w_away² > 0. Zero only if `away` is coplanar with s in the lift (a flat cell).
template <class NT>
NT power_growth(const std::array<RawPoint, 3>& s, const RawPoint& away, const Homog<NT>& d) {
  const SiteNT<NT> o(s[0]), l(away);
  const NT half(0.5);
  return o.w2 * (d.X * l.x + d.Y * l.y - half * d.Z) - l.w2 * (d.X * o.x + d.Y * o.y - half * d.Z);
}

// The direction of the power edge of three sites, pointing away from the fourth site `away`
// (the opposite vertex of the finite cell on the other side of the hull facet): the power of
// `away` must grow faster than that of s[0].
template <class NT>
std::optional<Homog<NT>> power_ray_direction(const std::array<RawPoint, 3>& s,
                                             const RawPoint& away) {
  const Homog<NT> d = power_line_direction<NT>(s);
  const auto st = certain_sign(power_growth(s, away, d));
  if (!st || *st == CGAL::ZERO) return std::nullopt;
  if (*st == CGAL::POSITIVE) return negated(d);
  return d;
}

template <class NT>
NT paraboloid_form(const Homog<NT>& p) {
  return p.Z * p.W - p.X * p.X - p.Y * p.Y;
}

template <class NT>
NT paraboloid_bilinear(const Homog<NT>& a, const Homog<NT>& b) {
  return NT(0.5) * (a.Z * b.W + b.Z * a.W) - a.X * b.X - a.Y * b.Y;
}

}  // namespace covmap::voronoi::engine
