#include "audit/verdict.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/readable_numbers.h"

namespace covmap::audit {
namespace {

// Upper tail of χ² with 3 degrees of freedom: erfc(√(t/2)) + √(2t/π) e^{−t/2}.
double chi2_3_tail(double t) {
  return std::erfc(std::sqrt(0.5 * t)) + std::sqrt(2.0 * t / M_PI) * std::exp(-0.5 * t);
}

}  // namespace

Judgement judge(const VerdictInput& in, double threshold3) {
  Judgement v;
  const double pos_var = in.reported_position_sigma * in.reported_position_sigma + in.position_floor * in.position_floor;
  const bool with_weight = in.dlogw.has_value();
  v.dof = with_weight ? 3 : 2;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  cov(0, 0) = in.var_x + pos_var;
  cov(1, 1) = in.var_y + pos_var;
  cov(0, 1) = cov(1, 0) = in.cov_xy;
  Eigen::Vector3d d(in.dx, in.dy, 0.0);
  if (with_weight) {
    const double s = in.reported_logw_sigma.value_or(0.0);
    cov(2, 2) = in.var_logw + s * s + in.logw_floor * in.logw_floor;
    d(2) = *in.dlogw;
  }
  const int n = v.dof;
  const Eigen::MatrixXd c = cov.topLeftCorner(n, n);
  const Eigen::VectorXd dd = d.head(n);
  // A NaN anywhere (an unknown uncertainty as much as an unknown difference) makes χ² NaN, which
  // is judged inconsistent below; LDLT alone may return a finite number past a NaN pivot.
  v.chi2 = cov.topLeftCorner(n, n).allFinite() && dd.allFinite() ? dd.dot(c.ldlt().solve(dd))
                                                                   : std::numeric_limits<double>::quiet_NaN();
  const double threshold = with_weight ? threshold3 : chi2_quantile_two_dof(threshold3);
  v.inconsistent = !(v.chi2 <= threshold);  // NaN counts as inconsistent: say so rather than pass
  // The reason: each component in metres / dB and in its own σ.
  // Fixed notation throughout (core/readable_numbers.h): people read these sentences.
  std::ostringstream r;
  const double dist = std::hypot(in.dx, in.dy);
  const double pos_sigma = std::sqrt(0.5 * (cov(0, 0) + cov(1, 1)));
  r << (v.inconsistent ? "inconsistent: " : "consistent: ") << "position off by " << metres(dist) << " ("
    << fixed(pos_sigma > 0 ? dist / pos_sigma : 0.0, 1) << " σ)";
  if (with_weight) {
    const double logw_sigma = std::sqrt(cov(2, 2));
    const double z = logw_sigma > 0 ? std::abs(*in.dlogw) / logw_sigma : 0.0;
    if (in.alpha) r << ", power off by " << fixed(10.0 * *in.alpha * *in.dlogw / std::log(10.0), 1) << " dB (" << fixed(z, 1) << " σ)";
    else r << ", weight off by a factor " << fixed(std::exp(*in.dlogw), 3) << " (" << fixed(z, 1) << " σ)";
  }
  r << "; χ² = " << fixed(v.chi2, 1) << " with " << v.dof << " degrees of freedom, threshold " << fixed(threshold, 1);
  v.reason = r.str();
  return v;
}

double chi2_tail(double x, int dof) { return dof == 2 ? std::exp(-0.5 * x) : chi2_3_tail(x); }

// χ²₂'s tail is exp(−t/2): the quantile of χ²₃'s tail probability at threshold3.
double chi2_quantile_two_dof(double threshold3) { return -2.0 * std::log(chi2_3_tail(threshold3)); }

}  // namespace covmap::audit
