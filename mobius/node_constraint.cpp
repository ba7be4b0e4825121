#include "mobius/node_constraint.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace covmap::mobius {

GeneralizedCircle NodeFrame::to_plane(const GeneralizedCircle& g) const {
  const Mobius m(Complex(unit, 0.0), origin, Complex(0.0, 0.0), Complex(1.0, 0.0), false);
  return m.apply(g);
}

NodeConstraint exact_fixed_set(const Mobius& h_total, double matrix_tolerance) {
  const double norm = std::max({std::abs(h_total.a()), std::abs(h_total.b()),
                                std::abs(h_total.c()), std::abs(h_total.d())});
  const double mt = matrix_tolerance * norm;
  NodeConstraint c;
  if (h_total.conjugated()) {
    const auto forms = h_total.fixed_set_forms();
    auto size = [](const GeneralizedCircle& x) { return std::abs(x.A) + std::abs(x.B) + std::abs(x.C); };
    const double n0 = size(forms[0]), n1 = size(forms[1]);
    const GeneralizedCircle& big = n0 >= n1 ? forms[0] : forms[1];
    const GeneralizedCircle& small = n0 >= n1 ? forms[1] : forms[0];
    const double ratio = std::min(n0, n1) / std::max(n0, n1);
    // Proportional forms (or a vanishing one) describe one circle.
    const double lambda = (small.A * big.A + std::real(std::conj(small.B) * big.B) + small.C * big.C) /
                          (big.A * big.A + std::norm(big.B) + big.C * big.C);
    const double residual = std::abs(small.A - lambda * big.A) + std::abs(small.B - lambda * big.B) +
                            std::abs(small.C - lambda * big.C);
    if (ratio < matrix_tolerance || residual <= matrix_tolerance * std::max(n0, n1)) {
      c.is_circle = true;
      c.circle = big;
    } else {
      c.points = intersect(forms[0], forms[1]);
      if (c.points.empty()) {
        const auto c0 = forms[0].centre(), c1 = forms[1].centre();
        const auto r0 = forms[0].radius(), r1 = forms[1].radius();
        if (c0 && c1 && r0 && r1) {
          const double between = std::abs(*c0 - *c1);
          c.gap = std::max(between - *r0 - *r1, std::abs(*r0 - *r1) - between);
        } else {
          c.gap = INFINITY;  // an imaginary circle or parallel lines: no point at all
        }
      }
    }
  } else {
    const Complex a = h_total.a(), b = h_total.b(), cc = h_total.c(), d = h_total.d();
    if (std::abs(b) <= mt && std::abs(cc) <= mt && std::abs(a - d) <= mt) {
      c.any = true;  // the identity: this node constrains nothing
    } else if (std::abs(cc) <= mt) {
      if (std::abs(d - a) > mt) c.points.push_back(b / (d - a));
    } else {
      // c z² + (d - a) z - b = 0
      const Complex disc = std::sqrt((d - a) * (d - a) + 4.0 * cc * b);
      c.points.push_back((-(d - a) + disc) / (2.0 * cc));
      c.points.push_back((-(d - a) - disc) / (2.0 * cc));
    }
  }
  return c;
}


GeneralizedCircle least_squares_fixed_circle(const Mobius& m) {
  const auto forms = m.fixed_set_forms();
  Eigen::Matrix<double, 2, 4> rows;
  for (int r = 0; r < 2; ++r) rows.row(r) << forms[r].A, forms[r].B.real(), forms[r].B.imag(), forms[r].C;
  Eigen::JacobiSVD<Eigen::Matrix<double, 2, 4>> svd(rows, Eigen::ComputeFullV);
  const Eigen::Vector4d f = svd.matrixV().col(0);
  return GeneralizedCircle{f(0), Complex(f(1), f(2)), f(3)};
}

std::optional<Complex> other_fixed_point(const Mobius& m, double identity_tolerance) {
  const Complex a = m.a(), b = m.b(), c = m.c(), d = m.d();
  const double norm = std::max({std::abs(a), std::abs(b), std::abs(c), std::abs(d)});
  if (std::abs(c) <= identity_tolerance * norm) return std::nullopt;  // fixes only the node (and ∞)
  // c z² + (d - a) z - b = 0; b ≈ 0 (the origin is fixed): the other root is (a - d) / c.
  const Complex other = (a - d) / c;
  if (std::abs(other) < identity_tolerance) return std::nullopt;
  return other;
}

}  // namespace covmap::mobius
