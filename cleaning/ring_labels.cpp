#include "cleaning/tolerances.h"
#include "cleaning/ring_labels.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.h"

namespace covmap::cleaning {


BoundaryIndex::BoundaryIndex(const std::vector<BoundaryRing>& rings, double snap, int threads)
    : rings_(rings), snap_(snap), grid_(tolerance::kRelabelRadius * snap) {
  std::size_t edges = 0;
  for (const BoundaryRing& r : rings) {
    first_edge_.push_back(edges);
    edges += r.size();
  }
  edges_.resize(edges);
  // Contiguous runs of rings on the threads, each into its own batch of grid entries and its own
  // range of edges; the batches are appended in ring order, so the grid is the one a single
  // thread builds.
  const int workers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads), std::max<std::size_t>(rings.size(), 1)));
  std::vector<UniformGrid::Batch> batches(static_cast<std::size_t>(workers), UniformGrid::Batch(grid_));
  parallel_chunks(rings.size(), workers, [&](std::size_t begin, std::size_t end, int worker) {
    UniformGrid::Batch& batch = batches[static_cast<std::size_t>(worker)];
    for (std::size_t r = begin; r < end; ++r) {
      const BoundaryRing& ring = rings[r];
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const std::size_t k = first_edge_[r] + i;
        const Point a = ring.points[i], b = ring.points[(i + 1) % ring.size()];
        batch.add_segment(static_cast<int>(k), a, b);
        const double length = ring.arc[i + 1] - ring.arc[i];
        edges_[k] = {a, {(b.x - a.x) / length, (b.y - a.y) / length}, length, ring.sensor};
      }
    }
  });
  grid_.append(std::move(batches));
  grid_.finish(threads);
}

Across BoundaryIndex::across_at(int ring, std::size_t edge, Point p, int sensor, double radius) const {
  const std::size_t own = first_edge_[ring] + edge;
  const Point d = edges_[own].u;
  const int own_sensor = rings_[ring].sensor;
  const double overhang = tolerance::kEdgeOverhang * snap_;
  double best = radius * radius;  // squared distances from here on
  std::size_t best_edge = std::numeric_limits<std::size_t>::max();
  Point best_q{};
  const auto consider = [&](int e) {
    const auto k = static_cast<std::size_t>(e);
    if (k == own) return;
    const Edge& other = edges_[k];
    const Point a = other.a, u = other.u;
    if (d.x * u.x + d.y * u.y > -tolerance::kAntiparallelCosine) return;
    if (sensor != kNone && other.sensor != sensor) return;
    // Facing: p's foot lies on the other edge, give or take the overhang. Without this, the edge
    // of a neighbour that ends at a junction would still claim p for up to s beyond its end.
    const double along = (p.x - a.x) * u.x + (p.y - a.y) * u.y;
    if (along < -overhang || along > other.length + overhang) return;
    const double t = std::clamp(along, 0.0, other.length);
    const Point q{a.x + u.x * t, a.y + u.y * t};
    const double dist = (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
    // Ties (an edge reported from two grid cells, or two edges meeting at q): the lower id.
    if (dist < best || (dist == best && k < best_edge)) {
      best = dist;
      best_edge = k;
      best_q = q;
    }
  };
  if (radius <= 0.5 * grid_.cell()) grid_.for_each_within_half_cell(p, consider);
  else grid_.for_each_near(p, consider);
  best = std::sqrt(best);
  Across out;
  if (best_edge == std::numeric_limits<std::size_t>::max()) return out;
  const Edge& nearest = edges_[best_edge];
  out.label = nearest.sensor == own_sensor ? kSelf : nearest.sensor;
  out.q = best_q;
  if (best <= tolerance::kTouching * snap_) {
    out.contact = Contact::kTouching;
  } else {
    // Left of the other copy's edge = inside the other cell (its cell is on its left).
    const Point a = nearest.a, u = nearest.u;
    const double side = u.x * (p.y - a.y) - u.y * (p.x - a.x);
    out.contact = side > 0.0 ? Contact::kOverlap : Contact::kGap;
  }
  return out;
}

Across BoundaryIndex::across(int ring, double s) const {
  std::size_t edge = 0;
  const Point p = rings_[ring].at(s, &edge);
  return across_at(ring, edge, p, kNone, snap_);
}

std::vector<Sample> sample_ring(const BoundaryIndex& index, int r) {
  const BoundaryRing& ring = index.rings()[static_cast<std::size_t>(r)];
  const double spacing = tolerance::kSampleSpacing * index.snap();
  std::vector<Sample> out;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const double l = ring.arc[i + 1] - ring.arc[i];
    const int pieces = std::max(1, static_cast<int>(std::ceil(l / spacing)));
    const Point a = ring.points[i], b = ring.points[(i + 1) % ring.size()];
    for (int k = 0; k < pieces; ++k) {
      const double t = (k + 0.5) / pieces;
      Sample sample;
      sample.p = {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
      sample.s = ring.arc[i] + l * t;
      sample.edge = static_cast<std::uint32_t>(i);
      sample.label = index.across_at(r, i, sample.p, kNone, index.snap()).label;
      out.push_back(sample);
    }
  }
  return out;
}

double locate_transition(const BoundaryIndex& index, int ring, double s0, double s1, int label0) {
  for (int k = 0; k < tolerance::kTransitionBisections; ++k) {
    const double mid = 0.5 * (s0 + s1);
    if (index.across(ring, mid).label == label0) s0 = mid;
    else s1 = mid;
  }
  return 0.5 * (s0 + s1);
}

}  // namespace covmap::cleaning
