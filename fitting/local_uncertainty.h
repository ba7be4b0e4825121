// How well the map pins each sensor down on its own: the 1-σ of its position and log weight with
// its neighbours held at their estimates (the conditional covariance from the sensor's own 3×3
// block of JᵀJ, over the boundary samples that involve it).
//
// Why not the joint covariance: the boundaries fix weights only up to a common factor, so a joint
// covariance needs a gauge (fitting/ holds one reference weight), and a weight's σ then grows with
// its distance from the reference along the adjacency graph — a statement about the chain of
// sensors between the two, not about the sensor. A verdict asks whether this sensor's report fits
// the map around it, which is the conditional question. The noise level is estimated robustly from
// the residuals (1.4826 × their median absolute value) and samples are down-weighted as by a Cauchy
// loss of the same scale, so a few bad chains do not shrink or inflate anyone's σ.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "fitting/refine.h"
#include "core/diagram.h"

namespace covmap::fitting {

struct LocalUncertainty {
  double sigma_x = 0.0, sigma_y = 0.0, cov_xy = 0.0, sigma_log_weight = 0.0;
  bool available = false;  // false: fewer than two neighbours' boundaries, or too few samples
};

// loss_scale: where the Cauchy down-weighting starts, in units of the noise level. range: R of
// refine_sites (RefineResult::range), needed when some samples are range edges (held, like the
// neighbours: a range edge then fixes its site's position and weight relative to R); a range edge
// counts as one more neighbour.
std::vector<LocalUncertainty> local_uncertainty(std::span<const Site> sites,
                                                std::span<const fitting::BoundarySample> samples,
                                                double loss_scale, std::optional<double> range = std::nullopt);

// The 1-σ of the reach R of refine_sites (RefineResult::range) from its spread between sites: each
// site with a range edge implies its own R_i (the median of |p − a| / w_a over its range samples);
// σ = 1.4826 · MAD(R_i) / √n. Unlike a σ with the sites held, it carries the weights' errors and
// the staircase's correlated noise along each edge. 0 with fewer than three such sites.
double range_sigma(std::span<const Site> sites, std::span<const fitting::BoundarySample> samples);

}  // namespace covmap::fitting
