#include "tools/mapgen/propagation_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "tools/mapgen/random_stream.h"

namespace covmap::mapgen {
namespace {

bool fail(std::string* why, const std::string& message) {
  if (why) *why = message;
  return false;
}

// z_i of the exponents model: standard normal clamped to ±3 so that α_i = α + spread·z_i stays
// positive whenever 3·spread < α (checked by is_valid).
constexpr double kExponentClamp = 3.0;

}  // namespace

std::string_view to_string(PropagationModel model) {
  switch (model) {
    case PropagationModel::kMultiplicative: return "multiplicative";
    case PropagationModel::kExponents: return "exponents";
    case PropagationModel::kExcessLoss: return "excess-loss";
    case PropagationModel::kShadowing: return "shadowing";
  }
  return "?";
}

std::optional<PropagationModel> propagation_model_from_string(std::string_view text) {
  for (const PropagationModel m : kAllPropagationModels)
    if (to_string(m) == text) return m;
  return std::nullopt;
}

bool PropagationOptions::is_valid(double alpha, std::string* why) const {
  if (!std::isfinite(alpha_spread) || alpha_spread < 0.0) return fail(why, "alpha spread must be finite and >= 0");
  if (!(kExponentClamp * alpha_spread < alpha))
    return fail(why, "alpha spread must be below alpha / 3 (every exponent stays positive)");
  if (!std::isfinite(excess_loss_max_db_per_km) || excess_loss_max_db_per_km < 0.0)
    return fail(why, "excess loss must be finite and >= 0 dB/km");
  if (!std::isfinite(shadowing_sigma_db) || shadowing_sigma_db < 0.0)
    return fail(why, "shadowing sigma must be finite and >= 0 dB");
  if (shadowing_correlation_m && !(std::isfinite(*shadowing_correlation_m) && *shadowing_correlation_m > 0.0))
    return fail(why, "shadowing correlation length must be finite and positive");
  return true;
}

Propagation draw_propagation(std::span<const Point> positions, std::span<const double> tx_power_dbm, double alpha,
                             const PropagationOptions& options, double mean_spacing_m, std::uint64_t seed) {
  std::string why;
  if (!options.is_valid(alpha, &why)) throw std::invalid_argument("invalid propagation options: " + why);
  if (positions.size() != tx_power_dbm.size())
    throw std::invalid_argument("draw_propagation: positions and powers differ in length");
  Propagation out;
  out.model = options.model;
  if (options.model == PropagationModel::kShadowing) {
    out.shadowing_correlation_m = options.shadowing_correlation_m.value_or(mean_spacing_m);
    if (!(std::isfinite(out.shadowing_correlation_m) && out.shadowing_correlation_m > 0.0))
      throw std::invalid_argument("draw_propagation: the shadowing correlation length must be positive");
    out.shadowing_amplitude_db = options.shadowing_sigma_db * std::sqrt(2.0 / kShadowingTerms);
    out.shadowing_limit_db = kShadowingClipSigmas * options.shadowing_sigma_db;
  }
  RandomStream random(seed, RandomPurpose::kPropagation);
  for (std::size_t k = 0; k < positions.size(); ++k) {
    SensorPropagation s;
    s.position = positions[k];
    s.tx_power_dbm = tx_power_dbm[k];
    s.alpha = alpha;
    switch (options.model) {
      case PropagationModel::kMultiplicative: break;
      case PropagationModel::kExponents:
        s.alpha = alpha + options.alpha_spread * std::clamp(random.normal(), -kExponentClamp, kExponentClamp);
        break;
      case PropagationModel::kExcessLoss:
        s.excess_db_per_m = random.uniform(0.0, options.excess_loss_max_db_per_km) / 1000.0;
        break;
      case PropagationModel::kShadowing:
        for (int t = 0; t < kShadowingTerms; ++t) {
          ShadowingTerm term;
          term.kx = random.normal() / out.shadowing_correlation_m;
          term.ky = random.normal() / out.shadowing_correlation_m;
          term.phase = random.uniform(0.0, 2.0 * std::numbers::pi);
          s.shadowing.push_back(term);
        }
        break;
    }
    out.sensors.push_back(std::move(s));
  }
  return out;
}

double shadowing_db(const Propagation& propagation, std::size_t k, Point p) {
  const SensorPropagation& s = propagation.sensors[k];
  if (s.shadowing.empty()) return 0.0;
  const double dx = p.x - s.position.x, dy = p.y - s.position.y;
  double sum = 0.0;
  for (const ShadowingTerm& t : s.shadowing) sum += std::cos(t.kx * dx + t.ky * dy + t.phase);
  return std::clamp(propagation.shadowing_amplitude_db * sum, -propagation.shadowing_limit_db,
                    propagation.shadowing_limit_db);
}

double received_power_dbm(const Propagation& propagation, std::size_t k, Point p) {
  const SensorPropagation& s = propagation.sensors[k];
  const double d = std::hypot(p.x - s.position.x, p.y - s.position.y);
  if (d == 0.0) return std::numeric_limits<double>::infinity();
  return s.tx_power_dbm - 10.0 * s.alpha * std::log10(d) - s.excess_db_per_m * d + shadowing_db(propagation, k, p);
}

double sensitivity_for_range(double reference_power_dbm, double alpha, double max_range_m) {
  return reference_power_dbm - 10.0 * alpha * std::log10(max_range_m);
}

}  // namespace covmap::mapgen
