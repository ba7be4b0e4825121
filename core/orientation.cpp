#include "core/orientation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "core/diagram.h"

namespace covmap {
namespace {

// Error-free transformations: a*b == p + e and a+b == s + e exactly (Shewchuk 1997; the product
// needs a fused multiply-add).
void two_product(double a, double b, double& p, double& e) {
  p = a * b;
  e = std::fma(a, b, -p);
}

void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  e = (a - av) + (b - bv);
}

// Exact sign of the sum of `terms`, by growing a non-overlapping expansion one term at a time
// (Shewchuk's Grow-Expansion with zero elimination). The last non-zero component of the expansion
// has the largest magnitude and therefore carries the sign.
int exact_sign_of_sum(std::span<const double> terms) {
  std::vector<double> expansion;
  expansion.reserve(terms.size());
  for (const double term : terms) {
    double q = term;
    std::vector<double> grown;
    grown.reserve(expansion.size() + 1);
    for (const double h : expansion) {
      double sum = 0.0;
      double err = 0.0;
      two_sum(q, h, sum, err);
      if (err != 0.0) grown.push_back(err);
      q = sum;
    }
    if (q != 0.0) grown.push_back(q);
    expansion = std::move(grown);
  }
  if (expansion.empty()) return 0;
  return expansion.back() > 0 ? 1 : -1;
}

int sign(double v) { return (v > 0) - (v < 0); }

}  // namespace

int orientation(Point a, Point b, Point c) {
  // Filter (Shewchuk's orient2d stage A): the rounded determinant has the right sign when its
  // magnitude exceeds (3 + 16 eps) eps times the sum of the magnitudes of its two products.
  const double left = (a.x - c.x) * (b.y - c.y);
  const double right = (a.y - c.y) * (b.x - c.x);
  const double det = left - right;
  constexpr double kEps = std::numeric_limits<double>::epsilon() / 2;  // unit roundoff
  constexpr double kBound = (3.0 + 16.0 * kEps) * kEps;
  if (std::abs(det) > kBound * (std::abs(left) + std::abs(right))) return sign(det);

  // Exact: first scale every coordinate by one power of two so the largest magnitude is in
  // [0.5, 1): that changes no sign and no mantissa, and keeps every product below 1, so none
  // overflows (coordinates near 1e308 would give NaN) and products of coordinates of similar
  // size do not underflow (a square of side 1e-162 would look collinear). Then expand the
  // determinant into six products of coordinates (no rounded differences) and sum their exact
  // two-double representations.
  int exponent = 0;
  std::frexp(std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y), std::abs(c.x), std::abs(c.y)}),
             &exponent);
  for (Point* p : {&a, &b, &c}) {
    p->x = std::ldexp(p->x, -exponent);
    p->y = std::ldexp(p->y, -exponent);
  }
  const std::array<std::array<double, 2>, 6> products = {{{b.x, c.y}, {-b.y, c.x}, {-b.x, a.y},
                                                          {b.y, a.x}, {-a.x, c.y}, {a.y, c.x}}};
  std::array<double, 12> terms{};
  for (std::size_t i = 0; i < products.size(); ++i) two_product(products[i][0], products[i][1], terms[2 * i], terms[2 * i + 1]);
  return exact_sign_of_sum(terms);
}

}  // namespace covmap
