// The propagation models and their raster: labels against brute force (the library's own power
// formula, bit for bit, and an independent re-implementation from truth.json's recorded
// parameters), reception limits, the models really differ from the MWVD, and the degenerate
// settings that must give the MWVD back.
#include "tools/mapgen/propagation_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tools/mapgen/coverage_map_generator.h"
#include "tools/mapgen/coverage_map_json.h"
#include "tools/mapgen/received_power_raster.h"
#include "mapgen_test_util.h"

namespace covmap::mapgen {
namespace {

using testing::brute_force_owner;
using testing::random_test_sites;

constexpr std::array<PropagationModel, 3> kOtherModels = {PropagationModel::kExponents, PropagationModel::kExcessLoss,
                                                          PropagationModel::kShadowing};

CoverageMap make_map(PropagationModel model, std::optional<double> max_range = std::nullopt, std::uint64_t seed = 7,
                     int n = 60) {
  const auto sites = random_test_sites(n, 20'000.0, 3.0, 11);
  CoverageMapOptions o;
  o.bin_size_m = 100.0;
  o.propagation.model = model;
  o.max_range_m = max_range;
  o.seed = seed;
  return generate_coverage_map(sites, o);
}

// Received power of sensor k at p from truth.json alone, written out from the documented formulas
// (datasets/maps/README.md), not from the library.
double documented_power(const OrderedJson& truth, std::size_t k, double px, double py) {
  const auto& g = truth["generator"];
  const auto& s = truth["sensors"][k];
  const double d = std::sqrt((px - s["x"].get<double>()) * (px - s["x"].get<double>()) +
                             (py - s["y"].get<double>()) * (py - s["y"].get<double>()));
  const std::string model = g.value("model", "multiplicative");
  const double alpha = model == "exponents" ? s["alpha"].get<double>() : g["alpha"].get<double>();
  double power = s["tx_power_dbm"].get<double>() - 10.0 * alpha * std::log10(d);
  if (model == "excess-loss") power -= s["excess_loss_db_per_km"].get<double>() * d / 1000.0;
  if (model == "shadowing") {
    double sum = 0.0;
    for (const auto& t : s["shadowing"])
      sum += std::cos(t[0].get<double>() * (px - s["x"].get<double>()) + t[1].get<double>() * (py - s["y"].get<double>()) +
                      t[2].get<double>());
    const double a = g["shadowing_sigma_db"].get<double>() * std::sqrt(2.0 / g["shadowing_terms"].get<double>());
    const double limit = g["shadowing_limit_db"].get<double>();
    power += std::max(-limit, std::min(limit, a * sum));
  }
  return power;
}

TEST(PropagationModel, NamesRoundTrip) {
  for (const PropagationModel m : kAllPropagationModels) EXPECT_EQ(propagation_model_from_string(to_string(m)), m);
  EXPECT_FALSE(propagation_model_from_string("Shadowing"));
  EXPECT_FALSE(propagation_model_from_string(""));
}

TEST(PropagationModel, InvalidOptionsAreRefused) {
  PropagationOptions o;
  o.alpha_spread = 1.2;  // 3 × 1.2 ≥ 3.5: an exponent could reach 0
  std::string why;
  EXPECT_FALSE(o.is_valid(3.5, &why));
  EXPECT_NE(why.find("alpha spread"), std::string::npos);
  o = {};
  o.excess_loss_max_db_per_km = -1.0;
  EXPECT_FALSE(o.is_valid(3.5, nullptr));
  o = {};
  o.shadowing_correlation_m = 0.0;
  EXPECT_FALSE(o.is_valid(3.5, nullptr));
  CoverageMapOptions m;
  m.propagation.alpha_spread = 2.0;
  EXPECT_FALSE(m.is_valid(nullptr));
}

// Every bin of every model, with and without a reception limit, equals the argmax of the library's
// received_power_dbm over all sensors: the pruning never drops a winner.
TEST(ReceivedPowerRaster, EqualsBruteForceArgmaxForEveryModel) {
  for (const PropagationModel model : kOtherModels) {
    for (const std::optional<double> range : {std::optional<double>{}, std::optional<double>{2500.0}}) {
      const CoverageMap map = make_map(model, range);
      const RasterGrid& g = map.raster.grid;
      const std::size_t n = map.propagation.sensors.size();
      ASSERT_EQ(n, map.truth.size());
      std::size_t uncovered = 0;
      for (int j = 0; j < g.ny; ++j) {
        for (int i = 0; i < g.nx; ++i) {
          const Point p{g.center_x(i), g.center_y(j)};
          int best = kNone;
          double best_power = -std::numeric_limits<double>::infinity();
          for (std::size_t k = 0; k < n; ++k) {
            const double power = received_power_dbm(map.propagation, k, p);
            if (power > best_power) best_power = power, best = static_cast<int>(k);
          }
          if (range && best_power < *map.sensitivity_dbm) best = kNone;
          uncovered += best == kNone;
          ASSERT_EQ(map.raster.labels[g.index(i, j)], best)
              << to_string(model) << (range ? " with range" : "") << " bin (" << i << ", " << j << ")";
        }
      }
      EXPECT_EQ(uncovered > 0, range.has_value()) << to_string(model);
    }
  }
}

// Long thin rasters (one bin wide, two bins high, ...) split only along their long side and still
// cover every bin exactly once with the brute-force owner.
TEST(ReceivedPowerRaster, ThinRastersEqualBruteForce) {
  const CoverageMap map = make_map(PropagationModel::kShadowing, 2500.0);
  for (const auto& [nx, ny] : {std::pair{1, 300}, std::pair{300, 1}, std::pair{2, 157}, std::pair{133, 3}, std::pair{1, 1}}) {
    RasterGrid g = map.raster.grid;
    g.nx = nx, g.ny = ny;
    const auto raster = received_power_raster(map.propagation, g, map.sensitivity_dbm);
    ASSERT_EQ(raster.labels.size(), g.bins());
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        int best = kNone;
        double best_power = -std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < map.truth.size(); ++k) {
          const double power = received_power_dbm(map.propagation, k, {g.center_x(i), g.center_y(j)});
          if (power > best_power) best_power = power, best = static_cast<int>(k);
        }
        if (best_power < *map.sensitivity_dbm) best = kNone;
        ASSERT_EQ(raster.labels[g.index(i, j)], best) << nx << " x " << ny << " bin (" << i << ", " << j << ")";
      }
    }
  }
}

// Labels against powers recomputed from truth.json's recorded per-sensor parameters by the
// documented formulas, at sampled bins; bins whose two best powers are within 1e-9 dB (where two
// implementations may round differently) are skipped.
TEST(ReceivedPowerRaster, LabelsFollowTheDocumentedFormulasOfTruthJson) {
  for (const PropagationModel model : kOtherModels) {
    const CoverageMap map = make_map(model, 3000.0);
    const OrderedJson truth = truth_json(map);
    ASSERT_EQ(truth["generator"]["model"], to_string(model));
    const double alpha = 3.5, p0 = 43.0;
    const double sensitivity = p0 - 10.0 * alpha * std::log10(3000.0);
    EXPECT_NEAR(truth["generator"]["sensitivity_dbm"].get<double>(), sensitivity, 1e-12);
    const RasterGrid& g = map.raster.grid;
    std::size_t checked = 0;
    for (std::size_t b = 0; b < g.bins(); b += 37) {
      const int i = static_cast<int>(b % static_cast<std::size_t>(g.nx)), j = static_cast<int>(b / static_cast<std::size_t>(g.nx));
      const double px = g.x0 + (i + 0.5) * g.bin, py = g.y0 + (j + 0.5) * g.bin;
      double first = -INFINITY, second = -INFINITY;
      int owner = kNone;
      for (std::size_t k = 0; k < truth["sensors"].size(); ++k) {
        const double power = documented_power(truth, k, px, py);
        if (power > first) second = first, first = power, owner = static_cast<int>(k);
        else second = std::max(second, power);
      }
      if (first - second < 1e-9 || std::abs(first - sensitivity) < 1e-9) continue;
      if (first < sensitivity) owner = kNone;
      ASSERT_EQ(map.raster.labels[b], owner) << to_string(model) << " bin " << b;
      ++checked;
    }
    EXPECT_GT(checked, g.bins() / 40) << to_string(model);
  }
}

// The models are applied: each non-MWVD map differs from the multiplicative map of the same
// sensors on a real share of its bins (and the multiplicative one is the MWVD, by brute force).
TEST(ReceivedPowerRaster, OtherModelsReallyDifferFromTheMultiplicativeMap) {
  const CoverageMap mwvd = make_map(PropagationModel::kMultiplicative);
  EXPECT_TRUE(mwvd.propagation.sensors.empty());
  EXPECT_FALSE(truth_json(mwvd)["generator"].contains("model"));
  std::vector<Site> sites;
  for (const auto& t : mwvd.truth) sites.push_back(Site{t.id, t.position.x, t.position.y, t.weight});
  const RasterGrid& g = mwvd.raster.grid;
  for (std::size_t b = 0; b < g.bins(); b += 101) {
    const int i = static_cast<int>(b % static_cast<std::size_t>(g.nx)), j = static_cast<int>(b / static_cast<std::size_t>(g.nx));
    ASSERT_EQ(mwvd.raster.labels[b], brute_force_owner(sites, g.center_x(i), g.center_y(j)));
  }
  for (const PropagationModel model : kOtherModels) {
    const CoverageMap other = make_map(model);
    ASSERT_EQ(other.raster.labels.size(), mwvd.raster.labels.size());
    std::size_t differ = 0;
    for (std::size_t b = 0; b < g.bins(); ++b) differ += other.raster.labels[b] != mwvd.raster.labels[b];
    EXPECT_GT(static_cast<double>(differ), 0.03 * static_cast<double>(g.bins())) << to_string(model);
  }
}

// With no spread (equal exponents, no excess loss, zero shadowing) every model is the MWVD again:
// argmax of P_i − 10·α·log10 d is argmin d / w_i. Bins where two sensors' d / w are within 1e-12
// relative (the two formulations may round differently) are not compared.
TEST(ReceivedPowerRaster, ModelsWithoutSpreadGiveTheMultiplicativeMap) {
  const CoverageMap mwvd = make_map(PropagationModel::kMultiplicative, 2500.0);
  std::vector<Site> sites;
  for (const auto& t : mwvd.truth) sites.push_back(Site{t.id, t.position.x, t.position.y, t.weight});
  for (const PropagationModel model : kOtherModels) {
    PropagationOptions o;
    o.model = model;
    o.alpha_spread = 0.0;
    o.excess_loss_max_db_per_km = 0.0;
    o.shadowing_sigma_db = 0.0;
    std::vector<Point> positions;
    std::vector<double> powers;
    for (const auto& t : mwvd.truth) positions.push_back(t.position), powers.push_back(t.tx_power_dbm);
    const Propagation p = draw_propagation(positions, powers, 3.5, o, 1000.0, 7);
    const auto raster = received_power_raster(p, mwvd.raster.grid, sensitivity_for_range(43.0, 3.5, 2500.0));
    const RasterGrid& g = mwvd.raster.grid;
    std::size_t compared = 0;
    for (std::size_t b = 0; b < g.bins(); ++b) {
      const int i = static_cast<int>(b % static_cast<std::size_t>(g.nx)), j = static_cast<int>(b / static_cast<std::size_t>(g.nx));
      std::vector<double> d;
      for (const auto& s : sites) d.push_back(std::hypot(g.center_x(i) - s.x, g.center_y(j) - s.y) / s.weight);
      std::sort(d.begin(), d.end());
      if (d[1] - d[0] < 1e-12 * d[0] || std::abs(d[0] - 2500.0) < 1e-9 * 2500.0) continue;
      ASSERT_EQ(raster.labels[b], mwvd.raster.labels[b]) << to_string(model) << " bin " << b;
      ++compared;
    }
    EXPECT_GT(compared, g.bins() * 99 / 100);
  }
}

// The reception limit means the same reach under every model for a sensor of weight 1 and the
// nominal exponent: the multiplicative map's covered area equals the MWVD rule's (max d / w), and
// under the other models covered bins have a best power at or above the sensitivity.
TEST(ReceivedPowerRaster, ReceptionLimitIsTheSensitivityOfMaxRange) {
  EXPECT_NEAR(sensitivity_for_range(43.0, 3.5, 10'000.0), 43.0 - 140.0, 1e-12);
  for (const PropagationModel model : kAllPropagationModels) {
    const CoverageMap map = make_map(model, 2000.0);
    const RasterGrid& g = map.raster.grid;
    std::vector<Site> sites;
    for (const auto& t : map.truth) sites.push_back(Site{t.id, t.position.x, t.position.y, t.weight});
    std::size_t covered = 0;
    for (std::size_t b = 0; b < g.bins(); ++b) covered += map.raster.labels[b] != kNone;
    EXPECT_GT(covered, 0u);
    EXPECT_LT(covered, g.bins()) << to_string(model);
    if (model == PropagationModel::kMultiplicative) {
      for (std::size_t b = 0; b < g.bins(); b += 13) {
        const int i = static_cast<int>(b % static_cast<std::size_t>(g.nx)), j = static_cast<int>(b / static_cast<std::size_t>(g.nx));
        ASSERT_EQ(map.raster.labels[b], brute_force_owner(sites, g.center_x(i), g.center_y(j), 2000.0));
      }
    }
  }
}

TEST(PropagationModel, ParametersFollowTheirDistributions) {
  const CoverageMap exponents = make_map(PropagationModel::kExponents, std::nullopt, 3, 400);
  double sum = 0.0;
  for (const auto& s : exponents.propagation.sensors) {
    EXPECT_GE(s.alpha, 3.5 - 3 * 0.3);
    EXPECT_LE(s.alpha, 3.5 + 3 * 0.3);
    sum += s.alpha;
  }
  EXPECT_NEAR(sum / 400.0, 3.5, 0.06);  // 4 standard errors of the mean
  const CoverageMap excess = make_map(PropagationModel::kExcessLoss, std::nullopt, 3, 400);
  for (const auto& s : excess.propagation.sensors) {
    EXPECT_GE(s.excess_db_per_m, 0.0);
    EXPECT_LE(s.excess_db_per_m, 3.0 / 1000.0);
  }
  // A shadowing field sampled far apart: mean ~0, std. deviation ~σ (the clip removes ~1 %), |S| ≤ 2.5σ.
  const CoverageMap shadowing = make_map(PropagationModel::kShadowing, std::nullopt, 3, 400);
  double s1 = 0.0, s2 = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < 400; ++k) {
    for (int t = 0; t < 50; ++t) {
      const Point p{shadowing.truth[k].position.x + 7000.0 * t, shadowing.truth[k].position.y - 3000.0 * t};
      const double v = shadowing_db(shadowing.propagation, k, p);
      EXPECT_LE(std::abs(v), 2.5 * 6.0 + 1e-12);
      s1 += v, s2 += v * v, ++count;
    }
  }
  EXPECT_NEAR(s1 / count, 0.0, 0.3);
  EXPECT_NEAR(std::sqrt(s2 / count), 6.0, 0.4);
}

TEST(PropagationModel, SameSeedSameMapOtherSeedOtherParameters) {
  for (const PropagationModel model : kOtherModels) {
    const CoverageMap a = make_map(model, 3000.0, 5), b = make_map(model, 3000.0, 5), c = make_map(model, 3000.0, 6);
    EXPECT_EQ(a.raster.labels, b.raster.labels);
    EXPECT_EQ(truth_json(a).dump(), truth_json(b).dump());
    const char* key = model == PropagationModel::kExponents    ? "alpha"
                      : model == PropagationModel::kExcessLoss ? "excess_loss_db_per_km"
                                                               : "shadowing";
    ASSERT_TRUE(truth_json(a)["sensors"][0].contains(key));
    EXPECT_NE(truth_json(a)["sensors"][0][key], truth_json(c)["sensors"][0][key]) << to_string(model);
  }
}

}  // namespace
}  // namespace covmap::mapgen
