// Which checker violations a test can hold the engine to on nearly degenerate input.
#pragma once

#include <algorithm>
#include <cmath>

#include "check/check.h"

namespace covmap::voronoi::testing {

// Nearly parallel bisectors (equal weights in a perturbed grid) and nearly equal weights
// (Apollonius circles of radius up to ~1e16 times the sites' spacing) put nodes and arcs far out,
// where the checker reaches its documented limit (docs/ENGINE.md, Limits): its first-order
// distance to a bisector overflows (it reports "inf off") far beyond the sites. Violations located
// beyond 1e6 times the extent are not counted; everything else the checker tests (every node and
// sample near the sites, sides, coverage, crossings) must pass.
inline bool judged(const check::Violation& v, double extent) {
  return !(std::max(std::fabs(v.x), std::fabs(v.y)) > 1e6 * extent);
}

}  // namespace covmap::voronoi::testing
