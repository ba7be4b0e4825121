#include "cleaning/range_edges.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "cleaning/curve_fit.h"
#include "cleaning/tolerances.h"

namespace covmap::cleaning {
namespace {

struct Bounds {
  double xmin = INFINITY, ymin = INFINITY, xmax = -INFINITY, ymax = -INFINITY;
  void add(Point p) {
    xmin = std::min(xmin, p.x), ymin = std::min(ymin, p.y);
    xmax = std::max(xmax, p.x), ymax = std::max(ymax, p.y);
  }
  bool near_side(Point p, double reach) const {
    return p.x - xmin <= reach || xmax - p.x <= reach || p.y - ymin <= reach || ymax - p.y <= reach;
  }
};

// Winding number of the sensor's rings about p (outer rings counter-clockwise, holes clockwise):
// positive inside its region.
int winding(const std::vector<const BoundaryRing*>& rings, Point p) {
  int w = 0;
  for (const BoundaryRing* ring : rings) {
    const auto& q = ring->points;
    for (std::size_t i = 0; i < q.size(); ++i) {
      const Point a = q[i], b = q[(i + 1) % q.size()];
      const double side = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
      if (a.y <= p.y && b.y > p.y && side > 0) ++w;
      if (a.y > p.y && b.y <= p.y && side < 0) --w;
    }
  }
  return w;
}

// Pieces of a frame chain off the bounding box's sides: maximal runs of vertices not within
// `reach` of a side (each run keeps the last box vertex before it and the first after, so a piece
// ends where the range edge meets the frame).
void pieces_off_box(const std::vector<Point>& points, const Bounds& box, double reach,
                    std::vector<std::vector<Point>>& out) {
  std::vector<Point> run;
  for (const Point& p : points) {
    if (box.near_side(p, reach)) {
      if (run.size() >= tolerance::kMinFitPoints) out.push_back(std::move(run));
      run.clear();
      continue;
    }
    run.push_back(p);
  }
  if (run.size() >= tolerance::kMinFitPoints) out.push_back(std::move(run));
}

// Is `fit` the range circle of a sensor whose region is `rings`?
bool is_reach_of(const FittedCurve& fit, const std::vector<const BoundaryRing*>& rings, double snap) {
  const Circle* c = std::get_if<Circle>(&fit.curve);
  if (!c || !(fit.rms <= tolerance::kRangeEdgeRms * snap)) return false;
  const Point centre{c->cx, c->cy};
  if (winding(rings, centre) <= 0) return false;
  const double limit = c->r + tolerance::kRangeDiscSlack * snap;
  for (const BoundaryRing* ring : rings)
    for (const Point& p : ring->points)
      if (std::hypot(p.x - centre.x, p.y - centre.y) > limit) return false;
  return true;
}

// The sensor's own ring vertices along `circle` (within kRangeEdgeBand snaps, off the box): runs of
// consecutive staircase corners whose edges run along it too (an edge's middle within the band: a
// long straight edge between two points of the circle is a chord, e.g. another boundary). The
// frame chains' points are simplified (Douglas–Peucker keeps a convex outline's outer corners),
// which would put a range edge ~0.4 bins outside its circle; the raw staircase alternates outer and
// inner corners about it.
std::vector<std::vector<Point>> raw_pieces(const std::vector<const BoundaryRing*>& rings, const Circle& circle,
                                           const Bounds& box, double snap) {
  std::vector<std::vector<Point>> out;
  const double band = tolerance::kRangeEdgeBand * snap, reach = tolerance::kFrameBoxReach * snap;
  for (const BoundaryRing* ring : rings) {
    const auto& q = ring->points;
    auto on_edge = [&](const Point& p) {
      return std::abs(std::hypot(p.x - circle.cx, p.y - circle.cy) - circle.r) <= band && !box.near_side(p, reach);
    };
    // Vertex k continues the run of k − 1 when it and the middle of their edge lie along the circle.
    const std::size_t n = q.size();
    auto continues = [&](std::size_t k) {
      const Point& a = q[(k + n - 1) % n];
      const Point& b = q[k];
      return on_edge(a) && on_edge(b) && on_edge({0.5 * (a.x + b.x), 0.5 * (a.y + b.y)});
    };
    // Start the walk at a break, so that no run is split at the ring's seam.
    std::size_t start = 0;
    while (start < n && continues(start)) ++start;
    if (start == n) {  // the whole ring is the edge: an isolated disc
      std::vector<Point> loop(q.begin(), q.end());
      loop.push_back(q.front());
      out.push_back(std::move(loop));
      continue;
    }
    std::vector<Point> run;
    for (std::size_t step = 0; step < n; ++step) {
      const std::size_t k = (start + step) % n;
      if (!continues(k)) {
        if (run.size() >= tolerance::kMinFitPoints) out.push_back(std::move(run));
        run.clear();
      }
      if (on_edge(q[k])) run.push_back(q[k]);
    }
    if (run.size() >= tolerance::kMinFitPoints) out.push_back(std::move(run));
  }
  return out;
}

FittedCurve fit_circle(const std::vector<std::vector<Point>>& pieces, double huber, double line_preference) {
  std::vector<Point> all;
  for (const auto& piece : pieces) all.insert(all.end(), piece.begin(), piece.end());
  return fit_curve(all, huber, line_preference, false);
}

}  // namespace

void find_range_edges(CleanedMap& map, const MapRings& rings, double snap, double huber, double line_preference) {
  Bounds box;
  for (const BoundaryRing& ring : rings.rings)
    for (const Point& p : ring.points) box.add(p);
  const std::size_t n = map.sensors.size();
  std::vector<std::vector<const BoundaryRing*>> rings_of(n);
  for (const BoundaryRing& ring : rings.rings) rings_of[static_cast<std::size_t>(ring.sensor)].push_back(&ring);
  std::vector<std::vector<std::vector<Point>>> candidates(n);
  for (const BoundaryChain& chain : map.chains)
    if (chain.sensor_b == kNone && chain.sensor_a != kNone)
      pieces_off_box(chain.points, box, tolerance::kFrameBoxReach * snap, candidates[static_cast<std::size_t>(chain.sensor_a)]);
  for (std::size_t s = 0; s < n; ++s) {
    if (candidates[s].empty()) continue;
    RangeEdge edge;
    edge.sensor = static_cast<int>(s);
    edge.fit = fit_circle(candidates[s], huber, line_preference);
    if (is_reach_of(edge.fit, rings_of[s], snap)) {
      edge.pieces = std::move(candidates[s]);
    } else if (candidates[s].size() > 1) {
      // Pieces that do not fit one circle together (a frame that is not the box's among them):
      // the pieces that are a reach on their own, then one circle through those.
      for (auto& piece : candidates[s])
        if (is_reach_of(fit_circle({piece}, huber, line_preference), rings_of[s], snap)) edge.pieces.push_back(std::move(piece));
      if (edge.pieces.empty()) continue;
      edge.fit = fit_circle(edge.pieces, huber, line_preference);
      if (!is_reach_of(edge.fit, rings_of[s], snap)) continue;
    } else {
      continue;
    }
    // The raw staircase along the circle found, and the circle refitted to it.
    // Twice: the first circle (of simplified corners) lies ~0.4 bins outside the staircase, and
    // the band about it would keep more outer corners than inner ones.
    for (int pass = 0; pass < 2; ++pass) {
      const Circle* c = std::get_if<Circle>(&edge.fit.curve);
      if (!c) break;
      std::vector<std::vector<Point>> raw = raw_pieces(rings_of[s], *c, box, snap);
      if (raw.empty()) break;
      const FittedCurve refit = fit_circle(raw, huber, line_preference);
      if (!is_reach_of(refit, rings_of[s], snap)) break;
      edge.pieces = std::move(raw), edge.fit = refit;
    }
    map.range_edges.push_back(std::move(edge));
  }
}

}  // namespace covmap::cleaning
