// covmap::mapgen propagation models: the received power of each sensor everywhere, for maps that
// the multiplicatively weighted Voronoi model (MWVD) does and does not explain.
//
// Received power of sensor i at distance d metres from it, dBm (P_i its transmit power, α the
// map's path-loss exponent):
//   kMultiplicative  P_i − 10·α·log10 d                      best server = argmin d / w_i (the MWVD)
//   kExponents       P_i − 10·α_i·log10 d                    α_i = α + alpha_spread·z_i, z_i ~ N(0, 1)
//                                                            clamped to [−3, 3]: each sensor its own
//                                                            path-loss exponent (antenna height, terrain)
//   kExcessLoss      P_i − 10·α·log10 d − γ_i·d              γ_i uniform in [0, excess_loss_max] dB/km:
//                                                            an extra loss growing linearly with distance
//                                                            (foliage, clutter, atmospheric absorption),
//                                                            different around each sensor
//   kShadowing       P_i − 10·α·log10 d + S_i(p)             S_i a smooth random field in dB per sensor
//                                                            (terrain shadowing): S_i(p) = clip(a·Σ_k cos(κ_k·(p − s_i) + φ_k)),
//                                                            k = 1..kShadowingTerms, κ_k ~ N(0, I/L²),
//                                                            φ_k uniform in [0, 2π), a = σ·√(2/K): mean 0,
//                                                            std. deviation σ, covariance ≈ σ²·exp(−|h|²/(2L²));
//                                                            clipped to ±kShadowingClipSigmas·σ
// The best server of a point is the sensor of largest received power (ties to the lowest index);
// with a sensitivity, a point whose best received power is below it is not covered. For the
// multiplicative model the sensitivity P0 − 10·α·log10(max_range) (P0 the power of a weight-1
// sensor) is exactly the generator's --max-range rule, and the other models use the same value:
// --max-range keeps meaning "the reach of the strongest sensor under the nominal model".
//
// Deterministic: the per-sensor parameters are drawn from RandomStream(seed, kPropagation), in
// sensor order, so the same seed gives the same parameters on every platform.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagram.h"

namespace covmap::mapgen {

enum class PropagationModel { kMultiplicative, kExponents, kExcessLoss, kShadowing };

// "multiplicative", "exponents", "excess-loss", "shadowing".
std::string_view to_string(PropagationModel model);
// The inverse of to_string; nullopt for any other text.
std::optional<PropagationModel> propagation_model_from_string(std::string_view text);
// Every model, in enum order (for option lists and tests).
inline constexpr std::array<PropagationModel, 4> kAllPropagationModels = {
    PropagationModel::kMultiplicative, PropagationModel::kExponents, PropagationModel::kExcessLoss,
    PropagationModel::kShadowing};

// Number of cosine terms of a shadowing field: enough for a field that looks Gaussian and smooth
// (the sum of 16 independent terms), few enough to evaluate 10^6 bins × a few candidates quickly.
inline constexpr int kShadowingTerms = 16;

// The shadowing field is clipped to ± this many σ. A truncated Gaussian, as simulations commonly
// use: it changes ~1 % of the field (the deepest fades and peaks) and bounds how far away a sensor
// can still win a point — 2·2.5σ = 30 dB at σ = 6 dB is a factor 10^(30/35) ≈ 7 in distance — which
// the raster's pruning needs: the unclipped sum could reach √(2K)·σ ≈ 5.7σ.
inline constexpr double kShadowingClipSigmas = 2.5;

struct PropagationOptions {
  PropagationModel model = PropagationModel::kMultiplicative;
  double alpha_spread = 0.3;               // kExponents: std. deviation of α_i around α
  double excess_loss_max_db_per_km = 3.0;  // kExcessLoss: γ_i is uniform in [0, this]
  double shadowing_sigma_db = 6.0;         // kShadowing: std. deviation of each field (6–8 dB is typical)
  // kShadowing: correlation length L of each field, metres. Unset: the sensors' mean
  // nearest-neighbour spacing (a field varies on the scale of a cell).
  std::optional<double> shadowing_correlation_m;

  // False, with the reason in *why, for negative spreads, 3·alpha_spread ≥ alpha (an exponent
  // could reach 0), or non-finite values. `alpha` is the map's nominal exponent.
  bool is_valid(double alpha, std::string* why) const;
};

struct ShadowingTerm {
  double kx = 0.0;     // wave vector, radians per metre
  double ky = 0.0;
  double phase = 0.0;  // radians
};

// One sensor's propagation, everything needed to evaluate its received power anywhere.
struct SensorPropagation {
  Point position;                 // plane, metres
  double tx_power_dbm = 0.0;      // P_i
  double alpha = 3.5;             // α_i (the nominal α except for kExponents)
  double excess_db_per_m = 0.0;   // γ_i in dB per metre (kExcessLoss; 0 otherwise)
  std::vector<ShadowingTerm> shadowing;  // kShadowing: kShadowingTerms terms; empty otherwise
};

struct Propagation {
  PropagationModel model = PropagationModel::kMultiplicative;
  double shadowing_amplitude_db = 0.0;  // a = σ·√(2/K) (kShadowing)
  double shadowing_limit_db = 0.0;      // the clip, kShadowingClipSigmas·σ (kShadowing)
  double shadowing_correlation_m = 0.0; // L as used (kShadowing)
  std::vector<SensorPropagation> sensors;
};

// The sensors' propagation under `options`: positions and powers as given, per-sensor parameters
// drawn from `seed`. mean_spacing_m fills an unset correlation length. Throws std::invalid_argument
// when the options are invalid or the spans differ in length.
Propagation draw_propagation(std::span<const Point> positions, std::span<const double> tx_power_dbm, double alpha,
                             const PropagationOptions& options, double mean_spacing_m, std::uint64_t seed);

// Sensor k's shadowing field at p, dB (0 without terms).
double shadowing_db(const Propagation& propagation, std::size_t k, Point p);
// Sensor k's received power at p, dBm, by the formula of its model; +infinity at the sensor itself.
double received_power_dbm(const Propagation& propagation, std::size_t k, Point p);
// The receiver sensitivity that gives a sensor of power reference_power_dbm and exponent alpha the
// reach max_range_m: P0 − 10·α·log10(max_range).
double sensitivity_for_range(double reference_power_dbm, double alpha, double max_range_m);

}  // namespace covmap::mapgen
