#include "mobius/mobius.h"

#include <cmath>

namespace covmap::mobius {

// On v = (z, 1): inversion of the generalized circle A|z|² + B̄z + Bz̄ + C = 0 is
//   z ↦ (-B z̄ - C) / (A z̄ + B̄)
// (circle A = 1, B = -c: (c z̄ - |c|² + r²)/(z̄ - c̄) = c + r²/conj(z - c); line A = 0: the mirror
// image, since B̄ z + B z̄ + C = 0 is fixed and the map is an involution).
Mobius Mobius::inversion(const GeneralizedCircle& g) {
  return Mobius(-g.B, Complex(-g.C, 0.0), Complex(g.A, 0.0), std::conj(g.B), true);
}

// (F ∘ G)(v) = M_F · op_F(M_G · op_G(v)), op = conjugation when flagged. Conjugation commutes with
// the matrix product as conj(M v) = M̄ v̄, so the matrix is M_F · (F conjugated ? M̄_G : M_G).
Mobius Mobius::after(const Mobius& g) const {
  const Complex ga = conjugated_ ? std::conj(g.a_) : g.a_;
  const Complex gb = conjugated_ ? std::conj(g.b_) : g.b_;
  const Complex gc = conjugated_ ? std::conj(g.c_) : g.c_;
  const Complex gd = conjugated_ ? std::conj(g.d_) : g.d_;
  return Mobius(a_ * ga + b_ * gc, a_ * gb + b_ * gd, c_ * ga + d_ * gc, c_ * gb + d_ * gd,
                conjugated_ != g.conjugated_);
}

// w = M op(v)  ⇒  op(v) = M⁻¹ w  ⇒  v = op(M⁻¹ w) = op(M⁻¹) op(w).
Mobius Mobius::inverse() const {
  Complex ia = d_, ib = -b_, ic = -c_, id = a_;  // adjugate: M⁻¹ up to the determinant
  if (conjugated_) ia = std::conj(ia), ib = std::conj(ib), ic = std::conj(ic), id = std::conj(id);
  return Mobius(ia, ib, ic, id, conjugated_);
}

SpherePoint Mobius::apply(const SpherePoint& z) const {
  if (!z) {  // ∞ ↦ a / c
    if (c_ == Complex(0.0, 0.0)) return std::nullopt;
    return a_ / c_;
  }
  const Complex w = conjugated_ ? std::conj(*z) : *z;
  const Complex den = c_ * w + d_;
  if (den == Complex(0.0, 0.0)) return std::nullopt;
  return (a_ * w + b_) / den;
}

// H' = M^{-H} op(H) M^{-1}, op = conjugation for anti-Möbius maps (see the header's derivation:
// w = M v̄ gives v̄ = M⁻¹w and v* H v = w* M^{-H} H̄ M^{-1} w).
GeneralizedCircle Mobius::apply(const GeneralizedCircle& g) const {
  // M⁻¹ up to a complex factor λ: the adjugate. The form is then scaled by |λ|², a positive real,
  // so inside and outside are preserved.
  const Complex ia = d_, ib = -b_, ic = -c_, id = a_;
  const Complex h00(g.A, 0.0), h11(g.C, 0.0);
  const Complex h01 = conjugated_ ? std::conj(g.B) : g.B;
  const Complex h10 = std::conj(h01);
  // N = H · M⁻¹
  const Complex n00 = h00 * ia + h01 * ic, n01 = h00 * ib + h01 * id;
  const Complex n10 = h10 * ia + h11 * ic, n11 = h10 * ib + h11 * id;
  // H' = (M⁻¹)^H · N
  GeneralizedCircle out;
  out.A = std::real(std::conj(ia) * n00 + std::conj(ic) * n10);
  out.B = std::conj(ia) * n01 + std::conj(ic) * n11;
  out.C = std::real(std::conj(ib) * n01 + std::conj(id) * n11);
  return out;
}

std::array<GeneralizedCircle, 2> Mobius::fixed_set_forms() const {
  // c|z|² + d z - a z̄ - b = 0. For a complex constant k, Re(k w) with w = d z - a z̄ is
  // 2Re(B̄ z) with B̄ = (k d - conj(k a))/2... written out for k = 1 (real part) and k = -i (imag).
  std::array<GeneralizedCircle, 2> forms;
  const Complex ks[2] = {Complex(1.0, 0.0), Complex(0.0, -1.0)};
  for (int t = 0; t < 2; ++t) {
    const Complex k = ks[t];
    // Re(k (c|z|² + d z - a z̄ - b)) = Re(k c)|z|² + Re(k d z) - Re(k a z̄) - Re(k b)
    // Re(k d z) - Re(k a z̄) = Re((k d) z) - Re(conj(k a) z) = Re((k d - conj(k a)) z) = 2Re(B̄ z)
    // with B̄ = (k d - conj(k a)) / 2.
    const Complex bbar = 0.5 * (k * d_ - std::conj(k * a_));
    forms[t] = GeneralizedCircle{std::real(k * c_), std::conj(bbar), -std::real(k * b_)};
  }
  return forms;
}

}  // namespace covmap::mobius
