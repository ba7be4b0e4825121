// covmap::voronoi::build_diagram — the multiplicatively weighted Voronoi diagram of weighted sites.
//
// Contract
//  - Input: sites with finite coordinates, finite positive weights and pairwise distinct
//    positions, within the supported range (engine/limits.h, docs/ENGINE.md "Supported input":
//    weight ratios up to 2^40, sites within 2^26 extents of the origin, no two closer than 2^-60
//    of the extent). Anything else throws InvalidSites naming every offending site (index and id)
//    and the limit; nothing is built. A diagram whose nodes would not fit in doubles at the
//    input's scale is refused the same way after construction.
//  - Never returns a diagram its own structural check rejects (engine/self_check.h): that throws
//    EngineFailure, an internal error.
//  - Output: a Diagram whose nodes are the points weighted-equidistant from ≥3 sites with no
//    site closer, and whose arcs are the maximal pieces of bisectors (Apollonius circles; lines for
//    equal weights) between consecutive nodes, unbounded ends marked kNone. All combinatorial
//    decisions (which sites meet, in which order, whether a node has degree > 3) are exact for the
//    given doubles: the engine triangulates the exactly lifted sites with filtered exact predicates
//    (engine/lifted_traits.h) and decides every paraboloid crossing by exact signs
//    (engine/edge_pattern.h). Only node coordinates and curve parameters are rounded.
//  - Degenerate input is welcome: equal weights, several maximal weights (unbounded arcs),
//    collinear or cocircular sites, nodes of any degree.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/diagram.h"

namespace covmap::voronoi {

struct InvalidSite {
  int index = kNone;
  std::string id;
  std::string problem;
};

class InvalidSites : public std::runtime_error {
 public:
  explicit InvalidSites(std::vector<InvalidSite> problems);
  const std::vector<InvalidSite>& problems() const { return problems_; }

 private:
  std::vector<InvalidSite> problems_;
};

// The engine's own check rejected the diagram it was about to return (engine/self_check.h): an
// internal error, never bad input — the engine refuses what it cannot build (InvalidSites) before
// returning anything else, so this signals a bug or a case outside what its arithmetic was shown to handle.
class EngineFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Every problem of the input, empty when it is valid: invalid values first; only when there are
// none, the supported range.
std::vector<InvalidSite> find_invalid_sites(std::span<const Site> sites);

struct BuildStats {
  int triangulation_dimension = 0;
  std::size_t exact_fallbacks = 0;  // decisions the interval filter could not take
  std::size_t exact_nodes = 0;      // nodes whose coefficients needed exact evaluation
  double triangulation_seconds = 0.0;
  double extraction_seconds = 0.0;
  double faces_seconds = 0.0;
  double self_check_seconds = 0.0;  // engine/self_check.h (part of extraction_seconds)
};

// Throws InvalidSites or EngineFailure. InvalidSites wins over anything else the build meets: small
// inputs are validated before any work, large ones (with finite values and positive weights) on a
// second thread during the triangulation, whose result is dropped if they are invalid.
// `stats` (optional) receives counters for benchmarks and reports.
Diagram build_diagram(std::span<const Site> sites, BuildStats* stats = nullptr);

}  // namespace covmap::voronoi
