#include "audit/alpha_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "audit/tolerances.h"

namespace covmap::audit {
namespace {

// The refined log weight is the regressor: the map fixes it far more tightly than powers are
// reported (rounded to 0.1–1 dB, often with a few dB of error), and noise in the regressor would
// bias the slope towards zero (alpha upwards); noise in the reported power, the response, does not.
struct PowerPoint {
  double log_weight;  // refined from the map, up to a common constant
  double power_dbm;   // reported
};

std::vector<PowerPoint> usable_points(std::span<const SensorAudit> sensors) {
  std::vector<PowerPoint> points;
  for (const SensorAudit& s : sensors) {
    if (!s.in_map || !s.reported || !s.reported->tx_power_dbm) continue;
    const double p = *s.reported->tx_power_dbm;
    if (!std::isfinite(p) || !(s.weight > 0) || !std::isfinite(s.weight)) continue;
    points.push_back({std::log(s.weight), p});
  }
  return points;
}

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2) return *mid;
  return (*mid + *std::max_element(v.begin(), mid)) / 2;
}

// Theil–Sen: the median slope over pairs of distinct powers; all pairs, or kAlphaMaxPairs drawn
// by a fixed-seed generator (std::mt19937_64's sequence is the same on every platform).
double median_pair_slope(const std::vector<PowerPoint>& pts) {
  std::vector<double> slopes;
  const auto add = [&](std::size_t i, std::size_t j) {
    const double dx = pts[j].log_weight - pts[i].log_weight;
    if (dx != 0) slopes.push_back((pts[j].power_dbm - pts[i].power_dbm) / dx);
  };
  const std::size_t n = pts.size();
  if (n * (n - 1) / 2 <= tolerance::kAlphaMaxPairs) {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) add(i, j);
  } else {
    std::mt19937_64 random(1);
    for (std::size_t k = 0; k < tolerance::kAlphaMaxPairs; ++k) add(random() % n, random() % n);
  }
  return slopes.empty() ? std::nan("") : median(std::move(slopes));
}

}  // namespace

std::optional<AlphaEstimate> estimate_alpha(std::span<const SensorAudit> sensors, std::optional<double> given_alpha) {
  const std::vector<PowerPoint> pts = usable_points(sensors);
  if (pts.size() < tolerance::kAlphaMinSensors) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.power_dbm < b.power_dbm; });
  if (hi->power_dbm - lo->power_dbm < tolerance::kAlphaMinPowerSpreadDb) return std::nullopt;
  // P = (10 alpha / ln 10) ln w + c: the slope b is alpha in dB per neper.
  const double b0 = median_pair_slope(pts);
  if (!(b0 > 0)) return std::nullopt;
  std::vector<double> offsets;
  for (const PowerPoint& p : pts) offsets.push_back(p.power_dbm - b0 * p.log_weight);
  const double a0 = median(offsets);
  std::vector<double> deviations;
  for (const double o : offsets) deviations.push_back(std::abs(o - a0));
  const double scale = 1.4826 * median(deviations);
  // Exact data have no scatter: then only what lies on the line (to rounding) is kept.
  const double limit = tolerance::kAlphaOutlierSigmas * scale + 1e-12 * (1 + std::abs(a0));
  double sx = 0, sy = 0, m = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (deviations[i] <= limit) sx += pts[i].log_weight, sy += pts[i].power_dbm, ++m;
  if (m < tolerance::kAlphaMinSensors) return std::nullopt;
  const double mx = sx / m, my = sy / m;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (deviations[i] <= limit) {
      sxx += (pts[i].log_weight - mx) * (pts[i].log_weight - mx);
      sxy += (pts[i].log_weight - mx) * (pts[i].power_dbm - my);
    }
  double syy = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (deviations[i] <= limit) syy += (pts[i].power_dbm - my) * (pts[i].power_dbm - my);
  if (!(sxx > 0) || !(sxy > 0) || !(syy > 0)) return std::nullopt;
  // Power on log weight (slope b: its errors in the weights pull alpha down) and log weight on
  // power (slope c: its errors in the powers pull alpha up) bracket the exponent.
  const double b = sxy / sxx, c = sxy / syy;
  double rss_y = 0, rss_x = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (deviations[i] <= limit) {
      rss_y += std::pow(pts[i].power_dbm - my - b * (pts[i].log_weight - mx), 2);
      rss_x += std::pow(pts[i].log_weight - mx - c * (pts[i].power_dbm - my), 2);
    }
  const double sigma_b = std::sqrt(rss_y / (m - 2) / sxx);
  const double sigma_c = std::sqrt(rss_x / (m - 2) / syy);
  const double to_alpha = std::log(10.0) / 10.0;  // alpha per dB-per-neper of slope
  AlphaEstimate e;
  e.low = b * to_alpha;
  e.sigma_low = sigma_b * to_alpha;
  // 1/c with c's σ: the high end is unbounded when c is not clearly above zero.
  const double inf = std::numeric_limits<double>::infinity();
  e.high = c > tolerance::kAlphaDisagreementSigmas * sigma_c ? to_alpha / c : inf;
  e.sigma_high = std::isfinite(e.high) ? e.high * sigma_c / c : inf;
  e.sensors = static_cast<std::size_t>(m);
  e.outliers = pts.size() - e.sensors;
  if (given_alpha) {
    const double a = *given_alpha;
    const double k = tolerance::kAlphaDisagreementSigmas;
    const bool below = a < e.low - k * e.sigma_low && a < e.low * (1 - tolerance::kAlphaDisagreementFraction);
    const bool above = std::isfinite(e.high) && a > e.high + k * e.sigma_high &&
                       a > e.high * (1 + tolerance::kAlphaDisagreementFraction);
    e.disagrees = below || above;
  }
  return e;
}

}  // namespace covmap::audit
