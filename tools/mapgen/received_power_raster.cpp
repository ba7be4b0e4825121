#include "tools/mapgen/received_power_raster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "tools/mapgen/tolerances.h"

namespace covmap::mapgen {
namespace {

using voronoi::BestServerRaster;
using voronoi::RasterGrid;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Blocks of at most this many bins are evaluated bin by bin over their survivors. Smaller than
// voronoi/best_server_raster.cpp's 64 because a shadowing field's range over a block tightens fast
// as the block shrinks; 8 was the fastest with shadowing, and the other models do not care.
constexpr long kLeafBins = 8;

// Path loss term P − 10·α·log10 d − γ·d, decreasing in d; +infinity at d = 0.
double path_power(const SensorPropagation& s, double d) {
  if (d == 0.0) return kInf;
  return s.tx_power_dbm - 10.0 * s.alpha * std::log10(d) - s.excess_db_per_m * d;
}

class Labeller {
 public:
  Labeller(const Propagation& propagation, const RasterGrid& grid, std::optional<double> sensitivity,
           std::vector<int>& labels)
      : p_(propagation), grid_(grid), sensitivity_(sensitivity), labels_(labels) {
  }

  void run() {
    std::vector<int> all(p_.sensors.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
    block(Block{0, grid_.nx - 1, 0, grid_.ny - 1}, all);
  }

 private:
  struct Bounds {
    double lower = 0.0;
    double upper = 0.0;
  };

  // Bounds on sensor k's path-loss term over the rectangle of bin centres [xlo, xhi] × [ylo, yhi]
  // (its value at the farthest and the nearest distance).
  Bounds path_bounds(int k, double xlo, double xhi, double ylo, double yhi) const {
    const SensorPropagation& s = p_.sensors[static_cast<std::size_t>(k)];
    const double nx = std::max({xlo - s.position.x, 0.0, s.position.x - xhi});
    const double ny = std::max({ylo - s.position.y, 0.0, s.position.y - yhi});
    const double fx = std::max(std::abs(s.position.x - xlo), std::abs(s.position.x - xhi));
    const double fy = std::max(std::abs(s.position.y - ylo), std::abs(s.position.y - yhi));
    return {path_power(s, std::hypot(fx, fy)), path_power(s, std::hypot(nx, ny))};
  }

  struct FieldRange {
    double lower = 0.0;
    double upper = 0.0;
  };

  // Range of sensor k's shadowing field over the rectangle, by Taylor's theorem about its centre c:
  // each term a·cos(θ_k(p)) with θ_k linear in p, |Δθ_k| ≤ |κ_kx|·hx + |κ_ky|·hy =: δ_k (hx, hy
  // the half sides), differs from its linearization at c by at most a·δ_k²/2, and the linear part by
  // at most |∂x(c)|·hx + |∂y(c)|·hy. The clip to ±limit is monotone, so it maps the range of the
  // sum onto the range of the field.
  FieldRange field_range(std::size_t k, double xlo, double xhi, double ylo, double yhi) const {
    const SensorPropagation& s = p_.sensors[k];
    const double a = p_.shadowing_amplitude_db;
    const double hx = 0.5 * (xhi - xlo), hy = 0.5 * (yhi - ylo);
    const double bound = p_.shadowing_limit_db;
    double curvature = 0.0;
    for (const ShadowingTerm& t : s.shadowing) {
      const double delta = std::abs(t.kx) * hx + std::abs(t.ky) * hy;
      curvature += 0.5 * delta * delta;
    }
    // A block much larger than the correlation length: the clip is the better bound, and it costs
    // no trigonometry.
    if (a * curvature >= 2.0 * bound) return {-bound, bound};
    const double dx = 0.5 * (xlo + xhi) - s.position.x, dy = 0.5 * (ylo + yhi) - s.position.y;
    double value = 0.0, gx = 0.0, gy = 0.0;
    for (const ShadowingTerm& t : s.shadowing) {
      const double theta = t.kx * dx + t.ky * dy + t.phase;
      const double sine = std::sin(theta);
      value += std::cos(theta);
      gx -= t.kx * sine;
      gy -= t.ky * sine;
    }
    const double spread = a * (std::abs(gx) * hx + std::abs(gy) * hy + curvature);
    return {std::clamp(a * value - spread, -bound, bound), std::clamp(a * value + spread, -bound, bound)};
  }

  // The candidates that can own a bin centre of the rectangle, ascending. Two stages: path-loss
  // bounds with the field's clip limit (cheap), then, for the sensors those cannot rule out, the
  // field's Taylor range (16 sines and cosines each); the best lower bound found so far prunes both.
  std::vector<int> survivors(const std::vector<int>& candidates, double xlo, double xhi, double ylo, double yhi) const {
    const double limit = p_.shadowing_limit_db;  // 0 without shadowing
    std::vector<Bounds> b(candidates.size());
    double best_lower = -kInf;
    std::size_t strongest = 0;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      b[c] = path_bounds(candidates[c], xlo, xhi, ylo, yhi);
      if (b[c].lower > b[strongest].lower) strongest = c;
    }
    best_lower = b[strongest].lower - limit;
    const auto keep_from = [&] {
      const double from = best_lower - tolerance::kPruneSlackDb;
      return sensitivity_ ? std::max(from, *sensitivity_ - tolerance::kPruneSlackDb) : from;
    };
    if (limit > 0.0) {
      // The strongest path first: its field range usually lifts best_lower most.
      std::vector<std::size_t> order(candidates.size());
      for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
      std::swap(order[0], order[strongest]);
      std::vector<bool> refined(candidates.size(), false);
      for (const std::size_t c : order) {
        if (b[c].upper + limit < keep_from()) continue;
        const FieldRange f = field_range(static_cast<std::size_t>(candidates[c]), xlo, xhi, ylo, yhi);
        b[c] = {b[c].lower + f.lower, b[c].upper + f.upper};
        refined[c] = true;
        best_lower = std::max(best_lower, b[c].lower);
      }
      for (std::size_t c = 0; c < b.size(); ++c)
        if (!refined[c]) b[c] = {b[c].lower - limit, b[c].upper + limit};
    }
    std::vector<int> kept;
    const double from = keep_from();
    for (std::size_t c = 0; c < candidates.size(); ++c)
      if (b[c].upper >= from) kept.push_back(candidates[c]);
    return kept;
  }

  // Bins i0..i1 × j0..j1 (inclusive).
  struct Block {
    int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
    long width() const { return i1 - i0 + 1; }
    long height() const { return j1 - j0 + 1; }
  };

  // `candidates`, ascending, holds every sensor that can own a bin of the block.
  void block(const Block& r, const std::vector<int>& candidates) {
    const std::vector<int> kept = survivors(candidates, grid_.center_x(r.i0), grid_.center_x(r.i1),
                                            grid_.center_y(r.j0), grid_.center_y(r.j1));
    if (kept.empty()) return;  // nobody reaches the sensitivity here: labels stay kNone
    if (kept.size() == 1 && !sensitivity_) {
      for (int j = r.j0; j <= r.j1; ++j)
        std::fill_n(labels_.begin() + static_cast<std::ptrdiff_t>(grid_.index(r.i0, j)), r.width(), kept[0]);
      return;
    }
    if (kept.size() == 1 || r.width() * r.height() <= kLeafBins) return per_bin(r, kept);
    // Quarter the block (halve only the longer side of a long thin one): fewer levels of bounds
    // than halving every time.
    const bool split_x = 2 * r.width() > r.height(), split_y = 2 * r.height() > r.width();
    const int mi = split_x ? r.i0 + static_cast<int>(r.width() / 2) - 1 : r.i1;
    const int mj = split_y ? r.j0 + static_cast<int>(r.height() / 2) - 1 : r.j1;
    block(Block{r.i0, mi, r.j0, mj}, kept);
    if (split_x) block(Block{mi + 1, r.i1, r.j0, mj}, kept);
    if (split_y) block(Block{r.i0, mi, mj + 1, r.j1}, kept);
    if (split_x && split_y) block(Block{mi + 1, r.i1, mj + 1, r.j1}, kept);
  }

  void per_bin(const Block& r, const std::vector<int>& kept) {
    for (int j = r.j0; j <= r.j1; ++j) {
      for (int i = r.i0; i <= r.i1; ++i) {
        const Point centre{grid_.center_x(i), grid_.center_y(j)};
        int best = kNone;
        double best_power = -kInf;
        for (const int k : kept) {  // ascending: strict > keeps the lowest index on ties
          const double power = received_power_dbm(p_, static_cast<std::size_t>(k), centre);
          if (best == kNone || power > best_power) {
            best_power = power;
            best = k;
          }
        }
        if (sensitivity_ && best_power < *sensitivity_) best = kNone;
        labels_[grid_.index(i, j)] = best;
      }
    }
  }

  const Propagation& p_;
  const RasterGrid& grid_;
  std::optional<double> sensitivity_;
  std::vector<int>& labels_;
};

}  // namespace

BestServerRaster received_power_raster(const Propagation& propagation, const RasterGrid& grid,
                                       std::optional<double> sensitivity_dbm) {
  if (grid.nx < 1 || grid.ny < 1) throw std::invalid_argument("received_power_raster: the grid has no bins");
  if (!(grid.bin > 0.0) || !std::isfinite(grid.bin))
    throw std::invalid_argument("received_power_raster: bin size must be positive");
  BestServerRaster out;
  out.grid = grid;
  out.labels.assign(grid.bins(), kNone);
  if (!propagation.sensors.empty()) Labeller(propagation, grid, sensitivity_dbm, out.labels).run();
  return out;
}

}  // namespace covmap::mapgen
