// Random site sets for engine tests, one generator per input family the engine must handle.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/diagram.h"

namespace covmap::voronoi::testing {

enum class Family {
  UniformWeights,   // weights uniform in [1, 2]
  EqualWeights,     // the ordinary Voronoi diagram
  WeightClasses,    // weights from {1, 2, 3}: many equal-weight pairs, lines and circles mixed
  SharedMaximum,    // several sites share the largest weight: unbounded arcs
  Grid,             // integer grid positions: cocircular and collinear sites, nodes of degree > 3
  Collinear,        // all sites on one line
  LargeCoordinates, // coordinates ~1e7, weight ratios up to 1e4
};

inline const char* family_name(Family f) {
  switch (f) {
    case Family::UniformWeights: return "UniformWeights";
    case Family::EqualWeights: return "EqualWeights";
    case Family::WeightClasses: return "WeightClasses";
    case Family::SharedMaximum: return "SharedMaximum";
    case Family::Grid: return "Grid";
    case Family::Collinear: return "Collinear";
    case Family::LargeCoordinates: return "LargeCoordinates";
  }
  return "?";
}

inline std::vector<Site> make_sites(Family family, int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Site> sites;
  auto add = [&](double x, double y, double w) {
    for (const Site& s : sites)
      if (s.x == x && s.y == y) return;  // positions must be distinct
    sites.push_back({std::to_string(sites.size()), x, y, w});
  };
  for (int i = 0; i < n; ++i) {
    switch (family) {
      case Family::UniformWeights: add(unit(rng), unit(rng), 1.0 + unit(rng)); break;
      case Family::EqualWeights: add(unit(rng), unit(rng), 2.5); break;
      case Family::WeightClasses: add(unit(rng), unit(rng), 1.0 + std::floor(3 * unit(rng))); break;
      case Family::SharedMaximum:
        add(unit(rng), unit(rng), unit(rng) < 0.3 ? 3.0 : 1.0 + 1.5 * unit(rng));
        break;
      case Family::Grid:
        add(std::floor(7 * unit(rng)), std::floor(7 * unit(rng)), unit(rng) < 0.5 ? 1.0 : 2.0);
        break;
      case Family::Collinear: {
        const double t = std::floor(50 * unit(rng));
        add(3 * t, -2 * t + 1, 1.0 + std::floor(3 * unit(rng)));
        break;
      }
      case Family::LargeCoordinates:
        add(1e7 + 1e5 * unit(rng), -1e7 + 1e5 * unit(rng), std::pow(10.0, 4 * unit(rng)));
        break;
    }
  }
  return sites;
}

// Nearly degenerate sets: an exactly degenerate base, each value then moved by a small amount.
// The engine must decide every such set exactly as the doubles say (a wrong decision on sites
// collinear to within an ulp puts arc ends hundreds of units off their curves).
enum class NearBase {
  Collinear,   // positions on the line y = x/2 (exact in doubles), weights uniform in [1, 3]
  Cocircular,  // equal weights on the integer points of the circle x² + y² = 65²: one node of degree 36
  Grid,        // a 7 x 7 integer grid, weights from {1, 2}: cocircular quadruples, collinear rows
  EqualWeight, // random positions, all weights 2.5: the perturbation makes them nearly equal
};

enum class Perturbation { Ulp, Rel1e15, Rel1e12, Rel1e9 };

inline const char* near_base_name(NearBase b) {
  switch (b) {
    case NearBase::Collinear: return "Collinear";
    case NearBase::Cocircular: return "Cocircular";
    case NearBase::Grid: return "Grid";
    case NearBase::EqualWeight: return "EqualWeight";
  }
  return "?";
}

inline const char* perturbation_name(Perturbation p) {
  switch (p) {
    case Perturbation::Ulp: return "Ulp";
    case Perturbation::Rel1e15: return "Rel1e15";
    case Perturbation::Rel1e12: return "Rel1e12";
    case Perturbation::Rel1e9: return "Rel1e9";
  }
  return "?";
}

// Moves v by the perturbation in a random direction (or not at all, a third of the time, so that
// exact degeneracies survive among the perturbed ones). `unit` stands in for |v| when v is 0.
inline double perturbed(double v, Perturbation p, double unit, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double r = u(rng);
  if (std::fabs(r) < 1.0 / 3) return v;
  if (p == Perturbation::Ulp)  // an ulp of `unit` at 0: a denormal would be refused, not tested
    return v != 0 ? std::nextafter(v, r > 0 ? HUGE_VAL : -HUGE_VAL) : std::copysign(0x1p-52 * unit, r);
  const double rel = p == Perturbation::Rel1e15 ? 1e-15 : p == Perturbation::Rel1e12 ? 1e-12 : 1e-9;
  return v + rel * (v != 0 ? std::fabs(v) : unit) * r;
}

// n sites (fewer for Cocircular and Grid if their base has fewer points) of the degenerate base
// with coordinates up to about `extent` (the integer bases are scaled by an integer, so that they
// stay exactly degenerate), each coordinate and weight then perturbed.
inline std::vector<Site> make_near_degenerate(NearBase base, Perturbation p, int n, double extent,
                                              std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const double integer_scale = std::max(1.0, std::floor(extent / 65));
  const double scale = base == NearBase::Grid ? std::max(1.0, std::floor(extent / 6))
                       : base == NearBase::Cocircular ? integer_scale
                                                      : extent;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::array<double, 3>> exact;
  switch (base) {
    case NearBase::Collinear:
      for (int i = 0; i < n; ++i) {
        const double x = scale * unit(rng);
        exact.push_back({x, x / 2, 1.0 + 2 * unit(rng)});
      }
      break;
    case NearBase::Cocircular:
      for (int x = -65; x <= 65; ++x)
        for (int y = -65; y <= 65; ++y)
          if (x * x + y * y == 65 * 65) exact.push_back({scale * x, scale * y, 2.5});
      std::shuffle(exact.begin(), exact.end(), rng);
      break;
    case NearBase::Grid:
      for (int x = 0; x < 7; ++x)
        for (int y = 0; y < 7; ++y) exact.push_back({scale * x, scale * y, unit(rng) < 0.5 ? 1.0 : 2.0});
      std::shuffle(exact.begin(), exact.end(), rng);
      break;
    case NearBase::EqualWeight:
      for (int i = 0; i < n; ++i) exact.push_back({scale * unit(rng), scale * unit(rng), 2.5});
      break;
  }
  if (static_cast<int>(exact.size()) > n) exact.resize(n);
  std::vector<Site> sites;
  for (const auto& e : exact) {
    const double x = perturbed(e[0], p, scale, rng), y = perturbed(e[1], p, scale, rng);
    // Weights stay exact except in EqualWeight, whose degeneracy they are.
    const double w = base == NearBase::EqualWeight ? perturbed(e[2], p, 1.0, rng) : e[2];
    const bool duplicate = std::any_of(sites.begin(), sites.end(), [&](const Site& s) { return s.x == x && s.y == y; });
    if (!duplicate) sites.push_back({std::to_string(sites.size()), x, y, w});
  }
  return sites;
}

}  // namespace covmap::voronoi::testing
