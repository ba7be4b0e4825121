// audit::estimate_sites — the recognition machinery run with tolerances on a cleaned
// coverage map, for starting values of the least-squares refinement.
//
// A cleaned map knows which sensor owns each face, but its arcs are fitted to staircases: no exact
// solution exists, so every exact test of recognize() becomes a least-squares problem:
//   - at each junction of ≥ 3 sensors, the composition of the inversions around it (in the
//     junction's own frame) has, for exact data, a circle of fixed points through the site
//     (Lemma 5, mobius/node_constraint.h); for noisy data the two real forms of its fixed-point
//     equation are only nearly proportional, and their principal direction is taken as the
//     solution circle (least_squares_fixed_circle). Junctions of even degree give a fixed point
//     instead, when the composition is not the identity (other_fixed_point).
//   - a sensor's position is the least-squares intersection of all its junctions' solution circles
//     and points (Gauss–Newton from every pairwise intersection and the cell's centroid; the start
//     with the smallest residual wins — the "candidate with the smaller residual"). A sensor
//     whose junctions leave it a choice (at most two solution circles and no point: two circles
//     meet at the site and once more; a hull sensor's two junctions are often the two vertices of
//     one triple, whose circles coincide) also takes, as points, the inversions of its
//     neighbours' sites across their common arcs (Lemma 1), for every neighbour its own junctions
//     determine; with no such neighbour, ties go to the point nearer its cell's centroid.
//   - weight ratios follow from Lemma 1 for every fitted circle (w_in / w_out =
//     sqrt(|c - s_in| / |c - s_out|), the geometric mean of its two estimates; 1 for lines), and
//     log weights are their least-squares solution over the sensor adjacency graph, weighted by
//     chain length, one gauge per connected component.
//   - sensors that no junction constrains take the inversion of a located neighbour across their
//     common boundary (Lemma 1), breadth first, else their cell's centroid.
// Never throws for bad geometry; `how` says where each estimate came from.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "cleaning/map_cleaning.h"
#include "core/diagram.h"

namespace covmap::audit {

enum class EstimateSource { kJunctions, kNeighbour, kCentroid };
std::string to_string(EstimateSource s);

struct SiteEstimates {
  std::vector<Site> sites;     // per cleaned sensor (ids from cleaning::CleanedMap::sensors), weight max 1
  std::vector<EstimateSource> how;
  std::vector<double> residual;         // rms distance to the sensor's solution circles (junctions only)
  std::vector<int> constraints;         // solution circles/points used per sensor
};

// centroids: per cleaned sensor, a point inside (or at the centre of) its cells, for starting values.
// threads: the sensors' junction solves run on up to this many; the result does not depend on it.
SiteEstimates estimate_sites(const cleaning::CleanedMap& map, std::span<const Point> centroids, int threads = 1);

}  // namespace covmap::audit
