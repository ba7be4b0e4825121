#include "mobius/generalized_circle.h"

#include <cmath>

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

}  // namespace covmap::mobius
