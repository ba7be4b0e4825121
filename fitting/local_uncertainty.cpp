#include "fitting/local_uncertainty.h"

#include <Eigen/Dense>
#include <algorithm>
#include <ceres/jet.h>
#include <cmath>
#include <stdexcept>

#include "fitting/residuals.h"
#include "fitting/tolerances.h"

namespace covmap::fitting {
namespace {

// Robust noise level: 1.4826 × the median absolute residual.
double robust_noise(std::span<const double> residual) {
  std::vector<double> absolute(residual.size());
  for (std::size_t k = 0; k < residual.size(); ++k) absolute[k] = std::abs(residual[k]);
  if (absolute.empty()) return 0.0;
  std::nth_element(absolute.begin(), absolute.begin() + absolute.size() / 2, absolute.end());
  return 1.4826 * absolute[absolute.size() / 2];
}

}  // namespace

std::vector<LocalUncertainty> local_uncertainty(std::span<const Site> sites,
                                                std::span<const fitting::BoundarySample> samples,
                                                double loss_scale, std::optional<double> range) {
  using Jet = ceres::Jet<double, 6>;
  const std::size_t n = sites.size();
  std::vector<double> residual(samples.size(), 0.0);
  std::vector<Eigen::Matrix<double, 1, 6>> gradient(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& s = samples[k];
    const auto& a = sites[s.site_a];
    Jet pa[3] = {Jet(a.x, 0), Jet(a.y, 1), Jet(std::log(a.weight), 2)};
    Jet r;
    if (s.site_b == kNone) {
      if (!range) throw std::invalid_argument("local_uncertainty: range-edge samples need the range R");
      const Jet log_range(std::log(*range));
      fitting::RangeResidual(s.p.x, s.p.y, 1.0)(pa, &log_range, &r);
    } else {
      const auto& b = sites[s.site_b];
      Jet pb[3] = {Jet(b.x, 3), Jet(b.y, 4), Jet(std::log(b.weight), 5)};
      fitting::BoundaryResidual(s.p.x, s.p.y, 1.0)(pa, pb, &r);
    }
    residual[k] = r.a;
    gradient[k] = r.v.transpose();
  }
  const double noise = robust_noise(residual);
  std::vector<Eigen::Matrix3d> info(n, Eigen::Matrix3d::Zero());
  // Boundaries with at least two different neighbours: along a single boundary the site can slide
  // with its weight (Lemma 1 fixes only its mirror relation to that one neighbour), and the 3×3
  // block is then nearly singular however many samples it holds.
  // A range edge (site_b = kNone) is enough alone: its circle about the site fixes all three of
  // the site's parameters (R held), unless the arc is too short (the conditioning test below).
  constexpr int kUnset = -2;
  std::vector<int> first_neighbour(n, kUnset);
  std::vector<char> two_neighbours(n, 0);
  auto meet = [&](int me, int other) {
    if (first_neighbour[me] == kUnset) first_neighbour[me] = other;
    else if (first_neighbour[me] != other) two_neighbours[me] = 1;
  };
  for (const auto& s : samples) {
    if (s.site_b == kNone) {
      two_neighbours[s.site_a] = 1;
      continue;
    }
    meet(s.site_a, s.site_b);
    meet(s.site_b, s.site_a);
  }
  const double c = loss_scale * noise;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (!gradient[k].allFinite() || !std::isfinite(residual[k])) continue;
    const double u = c > 0 ? residual[k] / c : 0.0;
    const double w = 1.0 / (1.0 + u * u);
    const Eigen::Vector3d ga = gradient[k].head<3>().transpose(), gb = gradient[k].tail<3>().transpose();
    info[samples[k].site_a] += w * ga * ga.transpose();
    if (samples[k].site_b != kNone) info[samples[k].site_b] += w * gb * gb.transpose();
  }
  std::vector<LocalUncertainty> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(info[i]);
    if (!two_neighbours[i] || eig.info() != Eigen::Success || !(eig.eigenvalues()(0) > tolerance::kLocalInformationConditioning * eig.eigenvalues()(2)) ||
        !(noise > 0))
      continue;
    const Eigen::Matrix3d cov = noise * noise * info[i].inverse();
    out[i] = {std::sqrt(cov(0, 0)), std::sqrt(cov(1, 1)), cov(0, 1), std::sqrt(cov(2, 2)), true};
  }
  return out;
}

double range_sigma(std::span<const Site> sites, std::span<const fitting::BoundarySample> samples) {
  std::vector<std::vector<double>> reach(sites.size());
  for (const auto& s : samples) {
    if (s.site_b != kNone) continue;
    const Site& a = sites[s.site_a];
    reach[s.site_a].push_back(std::hypot(s.p.x - a.x, s.p.y - a.y) / a.weight);
  }
  std::vector<double> per_site;
  for (auto& r : reach) {
    if (r.empty()) continue;
    std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
    per_site.push_back(r[r.size() / 2]);
  }
  if (per_site.size() < 3) return 0.0;
  std::nth_element(per_site.begin(), per_site.begin() + per_site.size() / 2, per_site.end());
  const double centre = per_site[per_site.size() / 2];
  for (double& r : per_site) r -= centre;
  return robust_noise(per_site) / std::sqrt(static_cast<double>(per_site.size()));
}

}  // namespace covmap::fitting
