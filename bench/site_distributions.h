// Random benchmark inputs: n sites with distinct positions uniform in the unit square and weights
// from one of three families.
//
//   uniform12              weight uniform in [1, 2]
//   uniform01              weight uniform in [0.1, 1.1]
//   correlated[:A:B]       the weights of §8 of "Computing the multiplicatively weighted Voronoi
//                          diagram via wavefronts" (Held & de Lorenzo):
//                            w = (A·d + B·r) / (A + B),
//                          d = distance to the centre of the square divided by the half-diagonal
//                          (so d ∈ [0, 1], as for their square of side √2 centred at the origin),
//                          r uniform in (0, 1]. Default A = B = 1; the paper used (1,0), (9,1),
//                          (7,3), (1,1), (0,1). A, B ≥ 0, A + B > 0; with B = 0 a site exactly
//                          at the centre would get weight 0 (the engine would reject it).
//
// Reproducible across standard libraries: only std::mt19937_64 and our own conversion to double are
// used. For a given (seed, n) the positions are the same for every distribution (the paper also
// compared weightings "for the same sets of points"); the weights use a separate stream.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/diagram.h"

namespace covmap::bench {

enum class WeightFamily { kUniform12, kUniform01, kCorrelated };

struct Distribution {
  WeightFamily family = WeightFamily::kUniform12;
  double alpha = 1.0;  // correlated only: weight of the distance term
  double beta = 1.0;   // correlated only: weight of the random term
  std::string name() const;  // round-trips through parse_distribution
};

// "uniform12", "uniform01", "correlated", "correlated:A:B"; nullopt (and a message) otherwise.
std::optional<Distribution> parse_distribution(const std::string& text, std::string* error);

std::vector<Site> make_sites(std::size_t n, const Distribution& dist, std::uint64_t seed);

}  // namespace covmap::bench
