// Input checks of refine_sites (its contract in fitting/refine.h lists what is accepted).
//
// Every problem is collected and reported in one std::invalid_argument, each naming the item —
// "initial[2] (site 'c')", "samples[17] (chain 4)", "priors[0]" — and what is wrong with it, so a
// caller with ten bad samples fixes them in one go. The first kMaxListed problems are spelled out.
#pragma once

#include <cstddef>
#include <span>

#include "fitting/refine.h"

namespace covmap::fitting::detail {

inline constexpr std::size_t kMaxListed = 20;

// Throws std::invalid_argument when any input is malformed; returns normally otherwise.
void validate_inputs(std::span<const Site> initial, std::span<const BoundarySample> samples,
                     std::span<const SitePrior> priors);

}  // namespace covmap::fitting::detail
