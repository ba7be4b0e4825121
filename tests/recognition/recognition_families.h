// Near-degenerate site sets for recognition round trips (bench/recognition_accuracy_bench and
// tests/recognition): the generator of each family, a relative perturbation of the coordinates, and
// a similarity transform (scale, rotation, translation) of the whole set. Ground truth for the
// round trip sites → engine → arc graph → recognize → sites.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/diagram.h"
#include "recognition/recognize.h"

namespace covmap::recognition::testing {

enum class RecognitionFamily {
  kRandom,      // uniform in the unit square, weights uniform in [1, 2]
  kEqual,       // uniform in the unit square, all weights 1 (the ordinary Voronoi diagram)
  kCollinear,   // on one slanted line, weights from {1, 2, 3}
  kCocircular,  // on one circle, all weights 1 (every node is the circle's centre)
  kGrid,        // integer grid, weights from {1, 2} (nodes of degree four, tangencies)
};

std::string to_string(RecognitionFamily family);
std::optional<RecognitionFamily> recognition_family_from_string(const std::string& name);

// How far each coordinate is moved, relative to the set's extent: 0, one unit in the last place
// (kUlp), or a relative amount drawn uniformly from [-amount, amount].
struct Perturbation {
  bool ulp = false;
  double amount = 0.0;
  std::string name() const;  // "0", "ulp", "1e-12", ...
};
std::optional<Perturbation> perturbation_from_string(const std::string& text);

// x ↦ offset + scale · R(angle) x, applied to positions (weights unchanged).
struct Similarity {
  double scale = 1.0;
  double angle = 0.0;  // radians
  double offset_x = 0.0, offset_y = 0.0;
};

// n sites of the family (fewer when positions coincide), perturbed, then transformed.
std::vector<Site> recognition_sites(RecognitionFamily family, int n, std::uint64_t seed, const Perturbation& p,
                                    const Similarity& t);

// Every number that states the graph (node coordinates, circle centres and radii, line points and
// directions) rounded to `digits` significant decimal digits, as a file written with that many
// digits would hold it. Sites and labels are left alone.
void round_graph(Diagram& g, int digits);

}  // namespace covmap::recognition::testing

namespace covmap::recognition::testing {

// A reconstruction against the sites that drew the graph, face by face: each traced face's
// reconstructed site against the site the engine labelled that face with (`drawn`: the engine's
// diagram, whose arcs recognize() keeps in order). Positions relative to the diagonal of the sites'
// bounding box; weights as the largest relative deviation of reconstructed/true weight from its
// value at the heaviest reconstructed site (weights are fixed up to one common factor).
struct RoundTripError {
  double position = 0.0;
  double weight = 0.0;
  int faces_compared = 0;
};
RoundTripError round_trip_error(const std::vector<Site>& truth, const Diagram& drawn,
                                const Reconstruction& r);

}  // namespace covmap::recognition::testing
