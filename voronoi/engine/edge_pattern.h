// Where the paraboloid crosses one edge of a power facet.
//
// An edge runs between homogeneous points A and B (finite power vertices or ray directions). On
// it, g(λA + μB) = λ² g(A) + 2λμ g(A,B) + μ² g(B) (λ, μ ≥ 0), a quadratic in Bernstein form, so
// only the signs of g(A), g(A,B), g(B) and of the discriminant g(A,B)² - g(A)g(B) decide how many
// zero points lie strictly inside the edge and the sign of g between them. No square roots.
#pragma once

#include <cstdint>
#include <optional>
#include <type_traits>

#include "voronoi/engine/power_geometry.h"

namespace covmap::voronoi::engine {

// No member initializers, so that the 3D extractor's array of facet patterns is allocated without
// touching its pages (every entry is written, on all cores): EdgePattern{} is the zero pattern,
// a default-initialized one is indeterminate.
struct EdgePattern {
  std::int8_t roots;    // interior zero points, in order from A to B (double root: 1)
  std::int8_t sign[3];  // sign of g before, between and after the roots
  bool empty;           // A and B are the same point: the edge has no interior
};
static_assert(std::is_trivially_default_constructible_v<EdgePattern>);

// Signs of g at the ends and of the bilinear form / discriminant decide the pattern.
inline EdgePattern pattern_from_signs(int sa, int sab, int sb, int sdisc) {
  EdgePattern p{};
  auto one = [&](int s) {
    p.roots = 0;
    p.sign[0] = static_cast<std::int8_t>(s);
    return p;
  };
  auto cross = [&](int before, int after) {
    p.roots = 1;
    p.sign[0] = static_cast<std::int8_t>(before);
    p.sign[1] = static_cast<std::int8_t>(after);
    return p;
  };
  if (sa == 0 && sb == 0) return one(sab);
  if (sa == 0) {  // g = μ (2 g(A,B) λ + g(B) μ): a second root iff the linear factor changes sign
    if (sab * sb < 0) return cross(sab, sb);
    return one(sb);
  }
  if (sb == 0) {
    if (sa * sab < 0) return cross(sa, sab);
    return one(sa);
  }
  if (sa != sb) return cross(sa, sb);
  // Same sign σ at both ends: the curve dips across zero only if the control value has sign -σ.
  if (sab != -sa || sdisc < 0) return one(sa);
  if (sdisc == 0) {
    p.roots = 1;
    p.sign[0] = p.sign[1] = static_cast<std::int8_t>(sa);
    return p;
  }
  p.roots = 2;
  p.sign[0] = p.sign[2] = static_cast<std::int8_t>(sa);
  p.sign[1] = static_cast<std::int8_t>(-sa);
  return p;
}

// nullopt when some sign is uncertain in interval arithmetic.
template <class NT>
std::optional<EdgePattern> edge_pattern(const Homog<NT>& a, const Homog<NT>& b) {
  const NT ga = paraboloid_form(a), gb = paraboloid_form(b), gab = paraboloid_bilinear(a, b);
  const auto sa = certain_sign(ga), sb = certain_sign(gb), sab = certain_sign(gab);
  if (!sa || !sb || !sab) return std::nullopt;
  if (*sa == 0 && *sb == 0) {
    // Both ends on ∂D: either a chord (g > 0 inside) or one point reached twice — two cells
    // sharing a power vertex on the paraboloid. Only then does identity matter.
    const auto m1 = certain_sign(a.X * b.W - b.X * a.W);
    const auto m2 = certain_sign(a.Y * b.W - b.Y * a.W);
    const auto m3 = certain_sign(a.Z * b.W - b.Z * a.W);
    const auto m4 = certain_sign(a.X * b.Y - b.X * a.Y);
    const auto m5 = certain_sign(a.X * b.Z - b.X * a.Z);
    const auto m6 = certain_sign(a.Y * b.Z - b.Y * a.Z);
    const auto sw = certain_sign(a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W);
    if (!m1 || !m2 || !m3 || !m4 || !m5 || !m6 || !sw) return std::nullopt;
    if (*m1 == 0 && *m2 == 0 && *m3 == 0 && *m4 == 0 && *m5 == 0 && *m6 == 0 && *sw > 0) {
      EdgePattern p{};
      p.empty = true;
      return p;
    }
  }
  int sd = 0;
  if (*sa != 0 && *sa == *sb && *sab == -*sa) {
    const auto s = certain_sign(gab * gab - ga * gb);
    if (!s) return std::nullopt;
    sd = *s;
  }
  return pattern_from_signs(*sa, *sab, *sb, sd);
}

}  // namespace covmap::voronoi::engine

namespace covmap::voronoi::engine {

// edge_pattern for an edge whose ends may be directions (W = 0). Between two directions the conic
// can only touch the line at infinity at a vertical direction; a double root there is the zero
// point U only if that direction points up, i.e. if the vertical combination κ a + b, with
// κ = -(a·b)_xy / |a_xy|², has positive height ∝ |a_xy|² b_z - (a·b)_xy a_z.
template <class NT>
std::optional<EdgePattern> edge_pattern_projective(const Homog<NT>& a, const Homog<NT>& b,
                                                   bool a_direction, bool b_direction) {
  auto p = edge_pattern(a, b);
  if (!p) return std::nullopt;
  if (!p->empty && a_direction && b_direction && p->roots == 1 && p->sign[0] == p->sign[1]) {
    const NT dot = a.X * b.X + a.Y * b.Y;
    auto s = certain_sign(b.Z * (a.X * a.X + a.Y * a.Y) - dot * a.Z);
    if (!s) return std::nullopt;
    if (*s <= 0) p->roots = 0;
  }
  return p;
}

// Whether a point (W > 0) or direction is a zero point of the walk: on the paraboloid, or U.
template <class NT>
std::optional<bool> is_zero_point(const Homog<NT>& p, bool direction) {
  if (direction) {
    // g = -(X² + Y²) vanishes on vertical directions, but only upward is on ∂D.
    auto sx = certain_sign(p.X), sy = certain_sign(p.Y), sz = certain_sign(p.Z);
    if (!sx || !sy || !sz) return std::nullopt;
    return *sx == 0 && *sy == 0 && *sz > 0;
  }
  auto sg = certain_sign(paraboloid_form(p));
  if (!sg) return std::nullopt;
  return *sg == 0;
}

}  // namespace covmap::voronoi::engine
