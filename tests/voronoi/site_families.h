// Random site sets for engine tests, one generator per input family the engine must handle.
#pragma once

#include <algorithm>
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

}  // namespace covmap::voronoi::testing
