// A generalized circle of the Riemann sphere — a circle or a line — in Hermitian form
//   A |z|² + B̄ z + B z̄ + C = 0,   A, C real, B complex,
// i.e. v* H v = 0 for v = (z, 1) and H = [[A, B], [B̄, C]]. A = 0 is a line (through ∞). The form is
// defined up to a real factor; the sign fixes an inside: points with A|z|²+2Re(B̄z)+C < 0.
#pragma once

#include <complex>
#include <optional>
#include <vector>

#include "core/diagram.h"

namespace covmap::mobius {

using Complex = std::complex<double>;

struct GeneralizedCircle {
  double A = 0.0;
  Complex B{0.0, 0.0};
  double C = 0.0;

  // The circle with centre c and radius r (inside = the disk).
  static GeneralizedCircle circle(Complex centre, double radius);
  // The line through p with direction d (inside = the left side of d).
  static GeneralizedCircle line(Complex p, Complex d);
  static GeneralizedCircle from(const Circle& c);
  static GeneralizedCircle from(const Line& l);

  bool is_line() const { return A == 0.0; }
  // Signed value of the form at z: negative inside, zero on it.
  double value(Complex z) const;
  // Centre and radius (circles only; nullopt for lines or an empty/imaginary circle).
  std::optional<Complex> centre() const;
  std::optional<double> radius() const;
};

// Distance from z to a generalized circle (exact for circles and lines; infinite for an empty or
// imaginary circle). Computed from the form, never from a centre and radius: a huge circle (nearly
// equal weights) is located near z to a few ulps of |z|, not to ulps of its radius.
double distance_to(const GeneralizedCircle& g, Complex z);

// The point of a generalized circle nearest to z (z itself at the centre or for an empty circle).
// Like distance_to, computed from the form without reading off a centre, so exact to a few ulps
// of |z| however large the circle.
Complex nearest_point(const GeneralizedCircle& g, Complex z);

// Intersection points of two generalized circles: 0, 1 or 2 (empty also when they coincide). Two
// circles whose discriminant is negative by less than tolerance::kTangentDiscriminant of its terms
// touch: one point.
std::vector<Complex> intersect(GeneralizedCircle a, GeneralizedCircle b);

}  // namespace covmap::mobius
