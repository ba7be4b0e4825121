#include "mobius/generalized_circle.h"

#include "mobius/tolerances.h"

#include <cmath>
#include <vector>
#include <utility>
#include <algorithm>

namespace covmap::mobius {

// |z - c|² - r² = |z|² - c̄ z - c z̄ + |c|² - r²  →  A = 1, B = -c, C = |c|² - r².
GeneralizedCircle GeneralizedCircle::circle(Complex centre, double radius) {
  return {1.0, -centre, std::norm(centre) - radius * radius};
}

// Left of d at p means Im(d̄ (z - p)) > 0. With B = -(i/2) d, 2 Re(B̄ z) = Re(i d̄ z) = -Im(d̄ z), so
// the form -Im(d̄ (z - p)) has B = -(i/2) d and C = Im(d̄ p), negative on the left.
GeneralizedCircle GeneralizedCircle::line(Complex p, Complex d) {
  const Complex i(0.0, 1.0);
  return {0.0, -0.5 * i * d, std::imag(std::conj(d) * p)};
}

GeneralizedCircle GeneralizedCircle::from(const Circle& c) {
  return circle({c.cx, c.cy}, c.r);
}
GeneralizedCircle GeneralizedCircle::from(const Line& l) {
  return line({l.x, l.y}, {l.dx, l.dy});
}

double GeneralizedCircle::value(Complex z) const {
  return A * std::norm(z) + 2.0 * std::real(std::conj(B) * z) + C;
}

std::optional<Complex> GeneralizedCircle::centre() const {
  if (A == 0.0) return std::nullopt;
  return -B / A;
}

std::optional<double> GeneralizedCircle::radius() const {
  if (A == 0.0) return std::nullopt;
  const double r2 = std::norm(B) / (A * A) - C / A;
  if (!(r2 > 0.0)) return std::nullopt;
  return std::sqrt(r2);
}

// Signed distance from z to a generalized circle (the sign of the form's value), from the form
// alone: with c = -B/A and r² = (|B|² - AC)/A², value(z) / (|Az + B| + √(|B|² - AC)) is
// sign(A)·(|z - c| - r) for a circle and the distance from the line (2|B| below) for a line.
// Reading c and r off a huge circle (nearly equal weights, r ~ 1e12 over an extent of 100) loses
// r·ε to the subtraction |z - c| - r; the form has no term of size r.
static double signed_distance(const GeneralizedCircle& g, Complex z) {
  const double root2 = std::norm(g.B) - g.A * g.C;
  if (!(root2 > 0.0)) return INFINITY;  // empty or imaginary circle
  const double denominator = std::abs(g.A * z + g.B) + std::sqrt(root2);
  return g.value(z) / denominator;
}

double distance_to(const GeneralizedCircle& g, Complex z) { return std::abs(signed_distance(g, z)); }

Complex nearest_point(const GeneralizedCircle& g, Complex z) {
  // The gradient of the form at z, A z + B, is along the normal through z (radial for a circle):
  // s·normal/|normal| = (|z - c| - r)(z - c)/|z - c|.
  const Complex normal = g.A * z + g.B;
  const double length = std::abs(normal);
  const double s = signed_distance(g, z);
  if (length == 0.0 || !std::isfinite(s)) return z;  // the centre, or no circle
  return z - s * normal / length;
}

// Intersection points of two generalized circles (0, 1 or 2; empty also when they coincide),
// without reading centres or radii off the forms: the pencil member A_b·a - A_a·b is a line through
// both points (the radical line), met with one of them by a quadratic in the arc length along it whose
// coefficients have no terms of size r (huge circles of nearly equal weights).
std::vector<Complex> intersect(GeneralizedCircle a, GeneralizedCircle b) {
  std::vector<Complex> out;
  if (a.is_line() && !b.is_line()) std::swap(a, b);
  if (a.is_line()) {  // two lines: 2Re(conj(B) z) + C = 0 each
    const double a1 = 2 * a.B.real(), b1 = 2 * a.B.imag(), a2 = 2 * b.B.real(), b2 = 2 * b.B.imag();
    const double det = a1 * b2 - a2 * b1;
    if (det == 0.0) return out;
    out.emplace_back((-a.C * b2 + b.C * b1) / det, (-a1 * b.C + a2 * a.C) / det);
    return out;
  }
  // a is a circle. The radical line (b itself when b is a line).
  const GeneralizedCircle line{0.0, b.A * a.B - a.A * b.B, b.A * a.C - a.A * b.C};
  if (std::abs(line.B) == 0.0) return out;  // concentric or identical circles
  // Line 2Re(conj(B) z) + C = 0: direction i·B, nearest point to the origin -C B / (2|B|²).
  const Complex p0 = -line.C * line.B / (2.0 * std::norm(line.B));
  const Complex dir = Complex(0, 1) * line.B / std::abs(line.B);
  // K(p0 + t dir) = A t² + 2 bq t + cq, met with whichever circle crosses the line more steeply:
  // disc / (|B|² - AC) = (half chord / radius)², the squared sine of the crossing angle (a line
  // nearly along a huge circle meets it ill-conditioned along the line).
  struct Quadratic {
    double A, bq, cq, disc, steepness;
  };
  auto quadratic = [&](const GeneralizedCircle& k) {
    const double bq = std::real(std::conj(k.A * p0 + k.B) * dir);
    const double cq = k.value(p0);
    const double disc = bq * bq - k.A * cq;
    return Quadratic{k.A, bq, cq, disc, disc / (std::norm(k.B) - k.A * k.C)};
  };
  Quadratic quad = quadratic(a);
  if (!b.is_line()) {
    const Quadratic other = quadratic(b);
    if (other.steepness > quad.steepness) quad = other;
  }
  const double bq = quad.bq, cq = quad.cq, disc = quad.disc;
  if (disc < 0) {
    if (disc > -tolerance::kTangentDiscriminant * (bq * bq + std::abs(quad.A * cq))) out.push_back(p0 - bq / quad.A * dir);
    return out;
  }
  // The root of larger size from the sum, the other from the product (no cancellation).
  const double q = -(bq + std::copysign(std::sqrt(disc), bq));
  if (q == 0.0) {  // bq = disc = 0: a double root at p0
    out.push_back(p0);
    return out;
  }
  out.push_back(p0 + (q / quad.A) * dir);
  out.push_back(p0 + (cq / q) * dir);
  return out;
}

}  // namespace covmap::mobius
