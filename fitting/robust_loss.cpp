#include "fitting/robust_loss.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fitting/tolerances.h"

namespace covmap::fitting::detail {
namespace {

// ρ(s) = c² log(1 + s/c²), as ceres::CauchyLoss, but with log1p.
class CauchyLoss final : public ceres::LossFunction {
 public:
  explicit CauchyLoss(double scale) : b_(scale * scale), c_(1.0 / b_) {}
  void Evaluate(double s, double rho[3]) const override {
    const double inv = 1.0 / (1.0 + s * c_);
    rho[0] = b_ * std::log1p(s * c_);
    rho[1] = inv;
    rho[2] = -c_ * inv * inv;
  }

 private:
  double b_, c_;
};

// ∫ g(z) φ(z) dz by composite Simpson over ±12 (the normal density beyond is below 1e-31).
template <typename G>
double gaussian_expectation(G g) {
  constexpr double kReach = 12.0;
  constexpr int kIntervals = 4800;  // even
  const double h = 2.0 * kReach / kIntervals;
  double sum = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double z = -kReach + i * h;
    const double simpson = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += simpson * g(z) * std::exp(-0.5 * z * z);
  }
  return sum * h / 3.0 / std::sqrt(2.0 * std::numbers::pi);
}

}  // namespace

std::unique_ptr<ceres::LossFunction> make_loss(RobustLoss loss, double scale) {
  switch (loss) {
    case RobustLoss::kNone: return nullptr;
    case RobustLoss::kHuber: return std::make_unique<ceres::HuberLoss>(scale);
    case RobustLoss::kCauchy: return std::make_unique<CauchyLoss>(scale);
  }
  return nullptr;
}

LossDerivatives loss_at(const ceres::LossFunction* loss, double r) {
  const double s = r * r;
  double rho[3] = {s, 1.0, 0.0};
  if (loss != nullptr) loss->Evaluate(s, rho);
  return {rho[1], r * rho[1], rho[1] + 2.0 * s * rho[2]};
}

double model_variance_factor(RobustLoss type, double scale) {
  const auto loss = make_loss(type, scale);
  if (loss == nullptr) return 1.0;
  const double w = gaussian_expectation([&](double z) { return loss_at(loss.get(), z).weight; });
  const double psi2 = gaussian_expectation([&](double z) {
    const double psi = loss_at(loss.get(), z).psi;
    return psi * psi;
  });
  const double dpsi = gaussian_expectation([&](double z) { return loss_at(loss.get(), z).dpsi; });
  return w * psi2 / (dpsi * dpsi);
}

double robust_noise_scale(std::span<const double> r, std::size_t free_parameters) {
  const double k2 = kScaleClip * kScaleClip;
  const double beta = gaussian_expectation([&](double z) { return std::min(z * z, k2); });
  const double target = (static_cast<double>(r.size()) - static_cast<double>(free_parameters)) * beta;
  double sum_squares = 0.0;
  for (double ri : r) sum_squares += ri * ri;
  if (!(sum_squares > 0) || !(target > 0)) return 0.0;
  // g(s) = Σ min((r/s)², k²) − target decreases in s; g(hi) ≤ 0 at hi = √(Σr²/target). Bisect on
  // log s over 60 orders of magnitude below hi: 200 halvings resolve s to ~1e-16 relative.
  const auto g = [&](double s) {
    double sum = 0.0;
    for (double ri : r) sum += std::min(ri * ri / (s * s), k2);
    return sum - target;
  };
  double log_hi = 0.5 * std::log(sum_squares / target), log_lo = log_hi - 60 * std::log(10.0);
  if (g(std::exp(log_lo)) <= 0) return std::exp(log_lo);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (log_lo + log_hi);
    (g(std::exp(mid)) > 0 ? log_lo : log_hi) = mid;
  }
  return std::exp(0.5 * (log_lo + log_hi));
}

VarianceFactor estimate_variance_factor(RobustLoss loss, double scale, std::span<const double> r,
                                        std::size_t free_parameters) {
  const std::size_t m = r.size();
  if (m <= free_parameters) {
    return {1.0, false,
            "noise level not estimable: " + std::to_string(m) + " samples for " + std::to_string(free_parameters) +
                " free parameters"};
  }
  double value = 0.0;
  if (loss == RobustLoss::kNone) {
    for (double ri : r) value += ri * ri;
    value /= static_cast<double>(m - free_parameters);
  } else {
    const double s = robust_noise_scale(r, free_parameters);
    value = s > 0 ? s * s * model_variance_factor(loss, scale / s) : 0.0;
  }
  return {std::max(value, tolerance::kMinVarianceFactor), true, ""};
}

}  // namespace covmap::fitting::detail
