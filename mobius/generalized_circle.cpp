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

// Distance from z to a generalized circle (|value| / |gradient| to first order, exact for circles
// and lines).
double distance_to(const GeneralizedCircle& g, Complex z) {
  if (g.is_line()) return std::abs(g.value(z)) / (2.0 * std::abs(g.B));
  const auto c = g.centre();
  const auto r = g.radius();
  if (!c || !r) return INFINITY;
  return std::abs(std::abs(z - *c) - *r);
}

// Intersection points of two generalized circles (0, 1 or 2; empty also when they coincide).
std::vector<Complex> intersect(GeneralizedCircle a, GeneralizedCircle b) {
  auto normalise = [](GeneralizedCircle g) {
    if (g.A != 0.0) {
      g.B /= g.A;
      g.C /= g.A;
      g.A = 1.0;
    }
    return g;
  };
  a = normalise(a);
  b = normalise(b);
  if (a.is_line() && !b.is_line()) std::swap(a, b);
  // Now a is a circle or both are lines. The radical line of two circles: a - b.
  GeneralizedCircle line = a;
  if (!a.is_line() && !b.is_line()) {
    line = GeneralizedCircle{0.0, a.B - b.B, a.C - b.C};
  } else if (b.is_line()) {
    line = b;
  }
  std::vector<Complex> out;
  if (a.is_line()) {  // two lines: 2Re(conj(B) z) + C = 0 each
    const double a1 = 2 * a.B.real(), b1 = 2 * a.B.imag(), a2 = 2 * b.B.real(), b2 = 2 * b.B.imag();
    const double det = a1 * b2 - a2 * b1;
    if (det == 0.0) return out;
    out.emplace_back((-a.C * b2 + b.C * b1) / det, (-a1 * b.C + a2 * a.C) / det);
    return out;
  }
  if (std::abs(line.B) == 0.0) return out;  // concentric or identical circles
  // Line 2Re(conj(B) z) + C = 0: direction i·B, nearest point to the origin -C B / (2|B|²).
  const Complex p0 = -line.C * line.B / (2.0 * std::norm(line.B));
  const Complex dir = Complex(0, 1) * line.B / std::abs(line.B);
  const Complex centre = *a.centre();
  const double r = std::sqrt(std::max(0.0, std::norm(centre) - a.C));
  // |p0 + t dir - c|² = r²
  const Complex w = p0 - centre;
  const double bq = std::real(std::conj(dir) * w);
  const double cq = std::norm(w) - r * r;
  const double disc = bq * bq - cq;
  if (disc < 0) {
    if (disc > -tolerance::kTangentDiscriminant * (r * r + std::norm(w))) out.push_back(p0 - bq * dir);
    return out;
  }
  const double s = std::sqrt(disc);
  out.push_back(p0 + (-bq - s) * dir);
  out.push_back(p0 + (-bq + s) * dir);
  return out;
}

}  // namespace covmap::mobius
