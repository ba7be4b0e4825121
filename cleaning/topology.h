// From labelled ring samples to the map's topology: boundary chains between junctions. Internal
// to map_cleaning.
//
// Along each ring, consecutive samples with one label form a run. Runs shorter than the shortest
// chain are too short to be a boundary of their own (a flicker at a junction, a cell one or two
// bins across): they and the places where the label changes make up the ring's junction
// candidates ("zones"). A zone between two runs of the same label with only outside or the sensor
// itself in between is no junction (a gap, or a seam, inside one boundary): the runs are joined
// through it. (A third cell in between, however small, is a real contact and stays a junction.) Zones of all rings
// whose points come within kJunctionMerge · s of each other are one junction (the same junction
// seen from each cell around it). Chains are read from one side only: a|b (a < b) from a's rings,
// frame chains from their cell's rings; the chain's points are the midpoints between the two
// copies of the boundary (frame chains: the ring's own vertices). Finally a junction where exactly
// two pieces of one boundary meet is dissolved (they are joined), and junctions no chain reaches
// are dropped.
#pragma once

#include <cstddef>
#include <vector>

#include "cleaning/ring_labels.h"
#include "core/diagram.h"

namespace covmap::cleaning {

struct RawChain {
  int sensor_a = kNone;  // a < b; b = kNone for a frame chain
  int sensor_b = kNone;
  int from = kNone;      // junction indices; both kNone for a closed loop
  int to = kNone;
  std::vector<Point> points;  // between the junctions (not including them), a on the left
};

struct Topology {
  std::vector<RawChain> chains;
  std::vector<Point> junctions;  // as the rings place them
  std::size_t junctions_merged = 0;
  std::size_t short_chains_dropped = 0;
  std::size_t gaps_closed = 0;
  std::size_t overlaps_resolved = 0;
  std::size_t seams = 0;  // stretches where two pieces of one sensor's region touch
};

// min_length: the shortest chain, in map units. Rings are sampled (sample_ring) and read in
// batches on `threads` threads, and their readings combined in ring order.
// threads: for sampling and reading the rings (the result is the same whatever the count).
Topology build_topology(const BoundaryIndex& index, double min_length, int threads = 1);

}  // namespace covmap::cleaning
