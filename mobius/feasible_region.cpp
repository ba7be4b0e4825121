#include "mobius/feasible_region.h"

#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>
#include <CGAL/Convex_hull_3/dual/halfspace_intersection_interior_point_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "mobius/mobius.h"
#include "mobius/tolerances.h"

namespace covmap::mobius {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Plane = K::Plane_3;
using Polyhedron = CGAL::Polyhedron_3<K>;

struct Vec3 {
  double x, y, t;
};

// The part of a facet's curve (where its plane meets the paraboloid) that lies inside the facet,
// as the midpoint of its longest piece. In the plane the curve is a circle, or a line for a
// vertical facet (a line constraint or a side of the window). Each facet edge keeps the curve
// where (X - P)·(n × e) ≥ 0, which along the curve is A cos θ + B sin θ + C (circle) or a
// quadratic in arc length (line); between consecutive roots of all edges the curve is either in
// the facet or not, and the midpoint of each such piece is tested against every edge.
std::optional<Complex> arc_midpoint(const std::vector<Vec3>& poly, const std::array<double, 4>& plane) {
  const auto [nx, ny, nt, d] = plane;
  const bool circle = std::abs(nt) > tolerance::kVerticalFacet * (std::abs(nx) + std::abs(ny));
  Complex c, u;
  double r = 0;
  if (circle) {
    c = Complex(-nx / (2 * nt), -ny / (2 * nt));
    const double r2 = std::norm(c) - d / nt;
    if (!(r2 > 0)) return std::nullopt;
    r = std::sqrt(r2);
  } else {
    const double len2 = nx * nx + ny * ny;
    c = -d * Complex(nx, ny) / len2;  // foot point of the line
    u = Complex(-ny, nx) / std::sqrt(len2);
  }
  auto point = [&](double p) { return circle ? c + std::polar(r, p) : c + p * u; };
  auto lifted = [](Complex z) { return Vec3{z.real(), z.imag(), std::norm(z)}; };
  const std::size_t n = poly.size();
  std::vector<Vec3> normals(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& a = poly[k];
    const Vec3& b = poly[(k + 1) % n];
    const Vec3 e{b.x - a.x, b.y - a.y, b.t - a.t};
    normals[k] = {ny * e.t - nt * e.y, nt * e.x - nx * e.t, nx * e.y - ny * e.x};  // n × e: into the facet
  }
  auto inside = [&](double p) {
    const Vec3 X = lifted(point(p));
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& a = poly[k];
      const Vec3& m = normals[k];
      if ((X.x - a.x) * m.x + (X.y - a.y) * m.y + (X.t - a.t) * m.t < 0) return false;
    }
    return true;
  };
  std::vector<double> roots;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& a = poly[k];
    const Vec3& m = normals[k];
    if (circle) {
      // h(θ) = C0 + A cos θ + B sin θ
      const double C0 = (c.real() - a.x) * m.x + (c.imag() - a.y) * m.y + (std::norm(c) + r * r - a.t) * m.t;
      const double A = r * m.x + 2 * r * c.real() * m.t, B = r * m.y + 2 * r * c.imag() * m.t;
      const double R = std::hypot(A, B);
      if (!(R > std::abs(C0))) continue;
      const double phi = std::atan2(B, A), delta = std::acos(-C0 / R);
      for (double t : {phi - delta, phi + delta}) {
        t = std::fmod(t, 2 * M_PI);
        roots.push_back(t < 0 ? t + 2 * M_PI : t);
      }
    } else {
      // h(s) = qa s² + qb s + qc
      const double qa = m.t;
      const double qb = u.real() * m.x + u.imag() * m.y + 2 * std::real(std::conj(c) * u) * m.t;
      const double qc = (c.real() - a.x) * m.x + (c.imag() - a.y) * m.y + (std::norm(c) - a.t) * m.t;
      if (qa == 0) {
        if (qb != 0) roots.push_back(-qc / qb);
        continue;
      }
      const double disc = qb * qb - 4 * qa * qc;
      if (disc < 0) continue;
      const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      if (q != 0) roots.push_back(q / qa), roots.push_back(qc / q);
    }
  }
  std::sort(roots.begin(), roots.end());
  if (circle) {
    if (roots.empty()) return inside(0.0) ? std::optional<Complex>(point(0.0)) : std::nullopt;
    roots.push_back(roots.front() + 2 * M_PI);  // the piece that wraps around
  }
  double best = 0.0;
  std::optional<Complex> out;
  for (std::size_t k = 0; k + 1 < roots.size(); ++k) {
    const double len = roots[k + 1] - roots[k];
    const double mid = 0.5 * (roots[k] + roots[k + 1]);
    if (len > best && inside(mid)) best = len, out = point(mid);
  }
  return out;
}

// The window: |x|, |y| ≤ 1 in normalised coordinates, as six lifted half-spaces (t bounded so the
// polyhedron is bounded; x² + y² ≤ 2 there).
constexpr std::array<std::array<double, 4>, 6> kBox{{{1, 0, 0, -1},
                                                     {-1, 0, 0, -1},
                                                     {0, 1, 0, -1},
                                                     {0, -1, 0, -1},
                                                     {0, 0, 1, -3},
                                                     {0, 0, -1, -1}}};

double window_margin(Complex z) { return 1.0 - std::max(std::abs(z.real()), std::abs(z.imag())); }

}  // namespace

double signed_distance_inside(const GeneralizedCircle& g, Complex z) {
  if (g.is_line()) return -g.value(z) / (2.0 * std::abs(g.B));
  // A|z|² + 2Re(B̄z) + C = A(|z - c|² - r²) with c = -B/A.
  const Complex c = -g.B / g.A;
  const double r2 = std::norm(c) - g.C / g.A;
  const double r = std::sqrt(std::max(0.0, r2));
  const double inside = r - std::abs(z - c);  // > 0 inside the disk
  return g.A > 0 ? inside : -inside;
}

FeasibleRegion feasible_region(std::span<const GeneralizedCircle> constraints, Complex window_centre,
                               double half_size) {
  if (!(half_size > 0) || !std::isfinite(half_size))
    throw std::invalid_argument("feasible_region: the window must have a positive finite size");
  // Normalise: z = centre + half_size · w, so the window is |Re w|, |Im w| ≤ 1 and the lifted
  // coordinates are all of order one.
  const Mobius to_window = Mobius(Complex(half_size, 0), window_centre, Complex(0, 0), Complex(1, 0), false).inverse();
  std::vector<GeneralizedCircle> local;
  local.reserve(constraints.size());
  std::vector<Plane> planes;
  planes.reserve(constraints.size() + kBox.size());
  for (const GeneralizedCircle& g : constraints) {
    if (g.A == 0.0 && g.B == Complex(0.0, 0.0))
      throw std::invalid_argument("feasible_region: a constraint is neither a circle nor a line");
    GeneralizedCircle w = to_window.apply(g);
    const double scale = std::max({std::abs(w.A), std::abs(w.B), std::abs(w.C)});
    w.A /= scale, w.B /= scale, w.C /= scale;
    local.push_back(w);
    // A t + 2Re(B) x + 2Im(B) y + C < 0 is the inside.
    planes.emplace_back(2 * w.B.real(), 2 * w.B.imag(), w.A, w.C);
  }
  for (const auto& b : kBox) planes.emplace_back(b[0], b[1], b[2], b[3]);

  FeasibleRegion out;
  const auto inner = CGAL::halfspace_intersection_interior_point_3(planes.begin(), planes.end());
  if (!inner) return out;  // the half-spaces have no common interior: no solution (Figure 4c)
  Polyhedron poly;
  CGAL::halfspace_intersection_3(planes.begin(), planes.end(), poly, *inner);

  auto margin_at = [&](Complex z) {
    double m = window_margin(z);
    for (const GeneralizedCircle& g : local) m = std::min(m, signed_distance_inside(g, z));
    return m;
  };
  struct Probe {
    Complex on;              // a point of the region's boundary, inside one boundary arc
    Complex inward;          // unit direction into the region
  };
  std::vector<Probe> probes;
  for (auto f = poly.facets_begin(); f != poly.facets_end(); ++f) {
    std::vector<Vec3> vs;
    auto h = f->facet_begin();
    do {
      const auto& p = h->vertex()->point();
      vs.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    } while (++h != f->facet_begin());
    if (vs.size() < 3) continue;
    // Outward normal (Newell), so that the polyhedron is n·X + d < 0.
    double nx = 0, ny = 0, nt = 0, cx = 0, cy = 0, ct = 0;
    for (std::size_t k = 0; k < vs.size(); ++k) {
      const Vec3& p = vs[k];
      const Vec3& q = vs[(k + 1) % vs.size()];
      nx += (p.y - q.y) * (p.t + q.t);
      ny += (p.t - q.t) * (p.x + q.x);
      nt += (p.x - q.x) * (p.y + q.y);
      cx += p.x, cy += p.y, ct += p.t;
    }
    const double n = std::sqrt(nx * nx + ny * ny + nt * nt);
    if (!(n > 0)) continue;
    nx /= n, ny /= n, nt /= n;
    const double cnt = static_cast<double>(vs.size());
    const double d = -(nx * cx + ny * cy + nt * ct) / cnt;
    const auto on = arc_midpoint(vs, {nx, ny, nt, d});
    if (!on) continue;  // the paraboloid misses this facet
    ++out.facets_crossed;
    // The facet's circle on the plane is g(x, y) = nx x + ny y + nt (x² + y²) + d; the region is
    // where g < 0, so inward is -∇g.
    const Complex grad(nx + 2 * nt * on->real(), ny + 2 * nt * on->imag());
    if (std::abs(grad) == 0.0) continue;
    probes.push_back({*on, -grad / std::abs(grad)});
  }
  // Step from the boundary into the region by halving lengths; keep the deepest point. At most
  // kMaxProbedFacets facets are probed (evenly spread), which bounds this part at O(k m).
  const std::size_t stride = std::max<std::size_t>(1, probes.size() / tolerance::kMaxProbedFacets);
  std::vector<std::pair<double, Complex>> starts;  // each probe's deepest point
  for (std::size_t k = 0; k < probes.size(); k += stride) {
    std::pair<double, Complex> deepest{0.0, probes[k].on};
    for (double step = 0.5; step > tolerance::kSmallestProbeStep; step *= 0.5) {
      const Complex z = probes[k].on + step * probes[k].inward;
      const double m = margin_at(z);
      if (m > deepest.first) deepest = {m, z};
    }
    if (deepest.first > 0) starts.push_back(deepest);
  }
  // The deepest region point is where the largest disk inside the region is centred: from the best
  // few starts, climb the margin (the distance to the nearest constraint) by a compass search.
  std::sort(starts.begin(), starts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  if (starts.size() > tolerance::kDeepestPointStarts) starts.resize(tolerance::kDeepestPointStarts);
  double best = 0.0;
  for (auto [m, z] : starts) {
    for (double step = 0.5 * m; step > tolerance::kSmallestProbeStep; step *= 0.5) {
      for (bool moved = true; moved;) {
        moved = false;
        for (int k = 0; k < 8; ++k) {
          const Complex t = z + std::polar(step, 0.7853981633974483 * k);
          const double mt = margin_at(t);
          if (mt > m) m = mt, z = t, moved = true;
        }
      }
    }
    if (m > best) best = m, out.representative = z;
  }
  if (!(best > 0)) return out;
  out.empty = false;
  out.margin = best * half_size;
  out.representative = window_centre + half_size * out.representative;
  return out;
}

}  // namespace covmap::mobius
