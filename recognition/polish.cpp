// Gauss-Newton polishing of a site on the solution circles of its face's nodes.
#include <cmath>

#include "recognition/recognize_stages.h"
#include "recognition/tolerances.h"

namespace covmap::recognition::stages {

mobius::Complex polish(mobius::Complex p, const std::vector<Constraint>& cs, double tol) {
  for (int it = 0; it < 4; ++it) {
    double jtj[3] = {0, 0, 0}, jtr[2] = {0, 0};
    int used = 0;
    for (const Constraint& c : cs) {
      if (!c.is_circle || c.circle.is_line()) continue;
      const auto centre = c.circle.centre();
      const auto radius = c.circle.radius();
      if (!centre || !radius) continue;
      const mobius::Complex d = p - *centre;
      const double len = std::abs(d);
      if (len == 0) continue;
      const double res = len - *radius;
      const double gx = d.real() / len, gy = d.imag() / len;
      jtj[0] += gx * gx, jtj[1] += gx * gy, jtj[2] += gy * gy;
      jtr[0] += gx * res, jtr[1] += gy * res;
      ++used;
    }
    if (used < 2) break;
    const double det = jtj[0] * jtj[2] - jtj[1] * jtj[1];
    if (!(std::abs(det) > tolerance::kSingularNormalEquations * (jtj[0] + jtj[2]) * (jtj[0] + jtj[2])))
      break;  // near-parallel circles
    const double dx = (jtj[2] * jtr[0] - jtj[1] * jtr[1]) / det;
    const double dy = (jtj[0] * jtr[1] - jtj[1] * jtr[0]) / det;
    if (!std::isfinite(dx) || !std::isfinite(dy) || std::hypot(dx, dy) > tol) break;
    p -= mobius::Complex(dx, dy);
  }
  return p;
}

}  // namespace covmap::recognition::stages
