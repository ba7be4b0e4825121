// Möbius and anti-Möbius transformations of the Riemann sphere, as 2×2 complex matrices:
//   z ↦ (a z + b) / (c z + d)        (holomorphic), or
//   z ↦ (a z̄ + b) / (c z̄ + d)        (conjugated: circle inversions and line reflections).
// Inversion in a circle and reflection in a line are the same object here, which is why the
// recognition code never distinguishes circles from lines (seed paper 5, §3.2 and §4.1). Matrices
// are kept up to a complex factor; composition multiplies them. Points are Riemann-sphere points:
// nullopt stands for ∞.
//
// Accepted: any coefficients. A transformation is invertible when ad - bc ≠ 0; that is the
// caller's to ensure (inversion() of a real circle or of a line, and compositions of them, are):
// a singular matrix is not detected and maps points to one point or to nothing meaningful.
// inversion() takes a form with a real, non-zero radius (A ≠ 0 and |B|² > AC) or a line (A = 0,
// B ≠ 0); a degenerate form gives a singular transformation.
// Guaranteed: plain floating-point arithmetic, no tolerance and no normalization: the matrices
// are not rescaled, so a long chain of compositions is the caller's to keep in range. apply(z)
// sends ∞ to a/c and a point whose denominator c·z + d (z conjugated first for anti-Möbius maps)
// is exactly zero to ∞ (nullopt). apply(circle) returns the image's form scaled by a positive real
// factor, so the image of a circle's inside (the form's negative side) is the inside of the
// image. after() and inverse() return matrices up to a complex factor.
// Rejected: nothing; nothing throws. NaN or infinite coefficients propagate into the results.
#pragma once

#include <array>
#include <optional>

#include "mobius/generalized_circle.h"

namespace covmap::mobius {

using SpherePoint = std::optional<Complex>;  // nullopt = ∞

class Mobius {
 public:
  Mobius() = default;  // the identity
  Mobius(Complex a, Complex b, Complex c, Complex d, bool conjugated)
      : a_(a), b_(b), c_(c), d_(d), conjugated_(conjugated) {}

  // Inversion in a generalized circle: z ↦ c + r² / conj(z - c) for a circle, the mirror image
  // for a line. Maps the circle's inside to its outside and fixes the circle pointwise.
  static Mobius inversion(const GeneralizedCircle& g);

  // (this ∘ g): apply g first, then this.
  Mobius after(const Mobius& g) const;
  Mobius inverse() const;

  SpherePoint apply(const SpherePoint& z) const;
  GeneralizedCircle apply(const GeneralizedCircle& g) const;

  // Points fixed by a conjugated transformation z = (a z̄ + b)/(c z̄ + d), i.e. the solutions of
  // c|z|² + d z - a z̄ - b = 0: the intersection of its real and imaginary parts, each a generalized
  // circle. Returned as those two forms; when they are proportional the fixed set is a circle.
  std::array<GeneralizedCircle, 2> fixed_set_forms() const;

  bool conjugated() const { return conjugated_; }
  Complex a() const { return a_; }
  Complex b() const { return b_; }
  Complex c() const { return c_; }
  Complex d() const { return d_; }

 private:
  Complex a_{1.0, 0.0}, b_{0.0, 0.0}, c_{0.0, 0.0}, d_{1.0, 0.0};
  bool conjugated_ = false;
};

}  // namespace covmap::mobius
