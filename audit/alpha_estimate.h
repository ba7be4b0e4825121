// The path-loss exponent the data imply. Each weight is w = 10^(P / (10 alpha)), so over the
// sensors that have a cell and a reported power, P is a line in ln w (refined from the map, up to
// one common factor) with slope 10 alpha / ln 10. The slope is found robustly (median of pairwise
// slopes, then least squares over the points within kAlphaOutlierSigmas of it: a power reported
// 6 dB off is left out), and alpha and its σ follow. A typed --alpha far from it (35 for 3.5) is named as disagreeing.
//
// Contract: nullopt with fewer than kAlphaMinSensors usable sensors, a power spread below
// kAlphaMinPowerSpreadDb, or a slope that is not positive (powers that do not grow with the
// weights: no alpha explains them). Deterministic: it depends only on `sensors`, in their order.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "audit/audit.h"

namespace covmap::audit {

std::optional<AlphaEstimate> estimate_alpha(std::span<const SensorAudit> sensors, std::optional<double> given_alpha);

}  // namespace covmap::audit
