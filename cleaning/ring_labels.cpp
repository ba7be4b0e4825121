#include "cleaning/tolerances.h"
#include "cleaning/ring_labels.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace covmap::cleaning {


BoundaryIndex::BoundaryIndex(const std::vector<BoundaryRing>& rings, double snap)
    : rings_(rings), snap_(snap), grid_(tolerance::kRelabelRadius * snap) {
  std::size_t edges = 0;
  for (const BoundaryRing& r : rings) {
    first_edge_.push_back(edges);
    edges += r.size();
  }
  edge_ring_.reserve(edges);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const BoundaryRing& ring = rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      grid_.add_segment(static_cast<int>(edge_ring_.size()), ring.points[i], ring.points[(i + 1) % ring.size()]);
      edge_ring_.push_back(static_cast<int>(r));
    }
  }
  grid_.finish();
}

Across BoundaryIndex::across_at(int ring, std::size_t edge, Point p, int sensor, double radius) const {
  const std::size_t own = first_edge_[ring] + edge;
  // An edge's start, unit direction and length, from its ring.
  const auto geometry = [&](std::size_t k, Point& a, Point& u, double& length) {
    const BoundaryRing& r = rings_[edge_ring_[k]];
    const std::size_t i = k - first_edge_[edge_ring_[k]];
    a = r.points[i];
    const Point b = r.points[(i + 1) % r.size()];
    length = r.arc[i + 1] - r.arc[i];
    u = {(b.x - a.x) / length, (b.y - a.y) / length};
  };
  Point own_start, d;
  double own_length = 0.0;
  geometry(own, own_start, d, own_length);
  const int own_sensor = rings_[ring].sensor;
  const double overhang = tolerance::kEdgeOverhang * snap_;
  double best = radius * radius;  // squared distances from here on
  std::size_t best_edge = std::numeric_limits<std::size_t>::max();
  Point best_q{};
  const auto consider = [&](int e) {
    const auto k = static_cast<std::size_t>(e);
    if (k == own) return;
    Point a, u;
    double length = 0.0;
    geometry(k, a, u, length);
    if (d.x * u.x + d.y * u.y > -tolerance::kAntiparallelCosine) return;
    const int other = rings_[edge_ring_[k]].sensor;
    if (sensor != kNone && other != sensor) return;
    // Facing: p's foot lies on the other edge, give or take the overhang. Without this, the edge
    // of a neighbour that ends at a junction would still claim p for up to s beyond its end.
    const double along = (p.x - a.x) * u.x + (p.y - a.y) * u.y;
    if (along < -overhang || along > length + overhang) return;
    const double t = std::clamp(along, 0.0, length);
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
  const int other = rings_[edge_ring_[best_edge]].sensor;
  out.label = other == own_sensor ? kSelf : other;
  out.q = best_q;
  if (best <= tolerance::kTouching * snap_) {
    out.contact = Contact::kTouching;
  } else {
    // Left of the other copy's edge = inside the other cell (its cell is on its left).
    Point a, u;
    double length = 0.0;
    geometry(best_edge, a, u, length);
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
