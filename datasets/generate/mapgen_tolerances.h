// Every fixed approximate comparison of the map generator, in one place. (Amounts a user sets —
// bin size, jitter, rounding digits, error sigmas — live in CoverageMapOptions with their
// documentation.)
#pragma once

namespace covmap::mapgen::tolerance {

// Best-server raster: a site is dropped from a block of bins only when its smallest possible
// weighted distance to the block exceeds the block's upper bound (or the maximum range) by more
// than this relative amount. Each bound and each per-bin distance sqrt(dx² + dy²) / w is computed
// with a relative error below 4 units in the last place (≈ 9e-16), so four of them compose to well
// under 1e-14; a slack of 1e-12 therefore never drops the site that the per-bin evaluation would
// have chosen, and costs nothing measurable (a site this close to the bound is kept one level
// longer). The labels themselves are decided by exact comparisons of the computed distances.
inline constexpr double kPruneRelativeSlack = 1e-12;

}  // namespace covmap::mapgen::tolerance
