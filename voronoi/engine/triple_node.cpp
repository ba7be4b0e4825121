#include "voronoi/engine/triple_node.h"

#include <cmath>
#include <optional>

#include "voronoi/tolerances.h"

namespace covmap::voronoi::engine {
namespace {

// The coefficients of triple_node.h, over a number type NT.
template <class NT>
struct Coefficients {
  NT nx, ny, h;     // the line p·n = h/2
  NT a, B, C, disc;  // a T² + 2 B T + C = 0, disc = B² − a C
};

template <class NT>
struct Differences {
  NT dx[2], dy[2], dw2[2], dd[2], wo2;
};

template <class NT>
Differences<NT> differences(const std::array<RawPoint, 3>& s) {
  Differences<NT> d;
  const NT ox(s[0].x()), oy(s[0].y()), ow(s[0].z());
  d.wo2 = ow * ow;
  for (int m = 0; m < 2; ++m) {
    const RawPoint& t = s[m + 1];
    d.dx[m] = NT(t.x()) - ox;
    d.dy[m] = NT(t.y()) - oy;
    d.dw2[m] = (NT(t.z()) - ow) * (NT(t.z()) + ow);  // factored: exact cancellation of equal weights
    d.dd[m] = d.dx[m] * d.dx[m] + d.dy[m] * d.dy[m];
  }
  return d;
}

template <class NT>
Coefficients<NT> coefficients(const std::array<RawPoint, 3>& s, int m) {
  const Differences<NT> d = differences<NT>(s);
  Coefficients<NT> c;
  c.nx = d.dw2[1] * d.dx[0] - d.dw2[0] * d.dx[1];
  c.ny = d.dw2[1] * d.dy[0] - d.dw2[0] * d.dy[1];
  c.h = d.dw2[1] * d.dd[0] - d.dw2[0] * d.dd[1];
  const NT n_dot_d = c.nx * d.dx[m] + c.ny * d.dy[m];
  const NT perp_dot_d = c.nx * d.dy[m] - c.ny * d.dx[m];  // perp(n)·d = −n_y d_x + n_x d_y
  const NT n2 = c.nx * c.nx + c.ny * c.ny;
  c.a = d.dw2[m];
  c.B = NT(2) * d.wo2 * perp_dot_d;
  c.C = c.a * c.h * c.h + NT(4) * d.wo2 * (c.h * n_dot_d - d.dd[m] * n2);
  c.disc = c.B * c.B - c.a * c.C;
  return c;
}

// The circumcentre of three equal-weight sites, relative to s[0]: p·d_m = |d_m|²/2.
template <class NT>
std::array<NT, 3> circumcentre_terms(const std::array<RawPoint, 3>& s) {
  const Differences<NT> d = differences<NT>(s);
  return {d.dd[0] * d.dy[1] - d.dd[1] * d.dy[0], d.dd[1] * d.dx[0] - d.dd[0] * d.dx[1],
          NT(2) * (d.dx[0] * d.dy[1] - d.dy[0] * d.dx[1])};
}

// Evaluates terms(NT) with running error bounds: the values, and in `relative` the largest bound
// relative to its value (infinite when a value is not known to be nonzero).
template <std::size_t K, class Terms>
std::array<double, K> fast_terms(Terms&& terms, double& relative) {
  const std::array<Approx, K> fast = terms(Approx{});
  std::array<double, K> out;
  relative = 0;
  for (std::size_t k = 0; k < K; ++k) {
    out[k] = fast[k].v;
    const double r = fast[k].e == 0 ? 0.0 : fast[k].e / std::fabs(fast[k].v);
    relative = std::isfinite(fast[k].v) && std::isfinite(r) ? std::max(relative, r) : HUGE_VAL;
  }
  return out;
}

template <std::size_t K, class Terms>
std::array<double, K> exact_terms(Terms&& terms) {
  const std::array<Exact, K> e = terms(Exact{});
  std::array<double, K> out;
  for (std::size_t k = 0; k < K; ++k) out[k] = CGAL::to_double(e[k]);
  return out;
}

// The node from coefficients each known to `relative` error is off by at most ~8 × relative ×
// its offset from s_0 (no step of the construction cancels: the roots are taken without
// cancellation and h n, T perp(n) are orthogonal). Good enough when that stays within
// tolerance::kNodeError of the extent and a few ulps of the node.
bool accurate(double relative, double ox, double oy, const Node& q, double extent) {
  if (!std::isfinite(relative) || !std::isfinite(q.x) || !std::isfinite(q.y)) return false;
  const double offset = std::hypot(q.x - ox, q.y - oy);
  const double magnitude = std::max(std::fabs(q.x), std::fabs(q.y));
  return 16 * relative * offset <= tolerance::kNodeError * extent + 4 * 0x1p-52 * magnitude;
}

// Fast coefficients, or exact ones when the node they give is not accurate enough.
template <std::size_t K, class Terms, class Construct>
Node construct(Terms&& terms, Construct&& node_from, double ox, double oy, double extent, bool* exact) {
  double relative = 0;
  const Node fast = node_from(fast_terms<K>(terms, relative));
  if (accurate(relative, ox, oy, fast, extent)) return fast;
  if (exact) *exact = true;
  return node_from(exact_terms<K>(terms));
}

bool equal_weights(const std::array<RawPoint, 3>& tri) {
  return tri[1].z() == tri[0].z() && tri[2].z() == tri[0].z();
}

// The reference equation: the larger |Δw_m²| (never 0 unless all weights are equal, and never the
// line bisector of two equal weights, on which F_m vanishes identically along the line).
int reference_site(const std::array<RawPoint, 3>& tri) {
  const double ow = tri[0].z();
  const double d1 = std::fabs((tri[1].z() - ow) * (tri[1].z() + ow));
  const double d2 = std::fabs((tri[2].z() - ow) * (tri[2].z() + ow));
  return d1 >= d2 ? 0 : 1;
}

}  // namespace

AlongLine wanted_root(const EdgePattern& p, int r, int sigma) {
  const bool first_of_travel = p.roots == 2 ? r == 0 : p.sign[0] <= p.sign[1];
  return first_of_travel == (sigma > 0) ? AlongLine::kFirst : AlongLine::kSecond;
}

int travel_sign(const std::array<RawPoint, 3>& tri, const RawPoint& away, bool leaving_finite) {
  // power_line_direction's (X, Y) is 2·perp(n); travelling away from `away`'s cell means that
  // `away`'s power grows faster than s[0]'s, i.e. power_growth < 0.
  const CGAL::Sign g = filtered_sign([&](auto tag) {
    using NT = decltype(tag);
    return power_growth(tri, away, power_line_direction<NT>(tri));
  });
  const int s = g == CGAL::NEGATIVE ? 1 : -1;
  return leaving_finite ? s : -s;
}

int travel_sign_planar(const std::array<RawPoint, 3>& tri) {
  const CGAL::Sign g = filtered_sign([&](auto tag) {
    using NT = decltype(tag);
    const Homog<NT> n = lifted_normal<NT>(tri), d = power_line_direction<NT>(tri);
    return n.X * d.X + n.Y * d.Y;
  });
  return g == CGAL::NEGATIVE ? -1 : 1;
}

bool same_root(const std::array<RawPoint, 3>& a, AlongLine wa, const std::array<RawPoint, 3>& b, AlongLine wb) {
  if (equal_weights(a) || equal_weights(b)) return true;
  const CGAL::Sign disc = filtered_sign([&](auto tag) { return coefficients<decltype(tag)>(a, reference_site(a)).disc; });
  if (disc == CGAL::ZERO) return true;
  const CGAL::Sign along = filtered_sign([&](auto tag) {
    using NT = decltype(tag);
    const auto na = coefficients<NT>(a, 0), nb = coefficients<NT>(b, 0);
    return na.nx * nb.nx + na.ny * nb.ny;
  });
  return (wa == wb) == (along == CGAL::POSITIVE);
}

Node triple_node(const std::array<RawPoint, 3>& tri, AlongLine which, double extent, bool* exact) {
  const double ox = tri[0].x(), oy = tri[0].y();
  if (equal_weights(tri))
    return construct<3>([&](auto tag) { return circumcentre_terms<decltype(tag)>(tri); },
                        [&](const std::array<double, 3>& t) { return Node{ox + t[0] / t[2], oy + t[1] / t[2]}; },
                        ox, oy, extent, exact);
  const int m = reference_site(tri);
  const auto terms = [&](auto tag) {
    const auto k = coefficients<decltype(tag)>(tri, m);
    return std::array{k.nx, k.ny, k.h, k.a, k.B, k.C, k.disc};
  };
  const auto node_from = [&](const std::array<double, 7>& c) {
    const double nx = c[0], ny = c[1], h = c[2], a = c[3], B = c[4], C = c[5], disc = c[6];
    // The two roots without cancellation: one from −B ∓ √disc, the other by Vieta.
    const double root = std::sqrt(std::max(disc, 0.0));
    const double big = B >= 0 ? -B - root : -B + root;
    double t1 = big / a, t2 = big != 0 ? C / big : t1;
    if (t1 > t2) std::swap(t1, t2);
    const double T = which == AlongLine::kFirst ? t1 : t2;
    const double n2 = nx * nx + ny * ny;
    return Node{ox + (h * nx - T * ny) / (2 * n2), oy + (h * ny + T * nx) / (2 * n2)};
  };
  return construct<7>(terms, node_from, ox, oy, extent, exact);
}

}  // namespace covmap::voronoi::engine
