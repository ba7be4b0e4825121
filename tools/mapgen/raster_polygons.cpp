#include "tools/mapgen/raster_polygons.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace covmap::mapgen {
namespace {

// Directions of unit boundary edges between grid corners, counter-clockwise order.
enum Direction : int { kEast = 0, kNorth = 1, kWest = 2, kSouth = 3 };
constexpr int kStepI[4] = {1, 0, -1, 0};
constexpr int kStepJ[4] = {0, 1, 0, -1};

class Tracer {
 public:
  Tracer(const std::vector<int>& labels, int nx, int ny) : labels_(labels), nx_(nx), ny_(ny) {}

  std::vector<GridPolygon> run(bool simplify) {
    label_components();
    std::vector<GridPolygon> polygons(component_label_.size());
    for (std::size_t c = 0; c < polygons.size(); ++c) {
      polygons[c].label = component_label_[c];
      polygons[c].bins = component_bins_[c];
    }
    // Every boundary edge belongs to exactly one ring; an edge is identified by its start corner
    // and direction, which also fixes the bin on its left.
    visited_.assign(static_cast<std::size_t>(nx_ + 1) * static_cast<std::size_t>(ny_ + 1) * 4, false);
    std::vector<std::vector<GridRing>> holes(polygons.size());
    for (int j = 0; j < ny_; ++j) {
      for (int i = 0; i < nx_; ++i) {
        const int c = component(i, j);
        if (c < 0) continue;
        // The bin's four sides, each directed with the bin on its left.
        const GridVertex starts[4] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
        for (int d = 0; d < 4; ++d) {
          if (!is_boundary(starts[d], d, c) || visited_[edge_key(starts[d], d)]) continue;
          GridRing ring = trace(starts[d], d, c, simplify);
          if (twice_signed_area(ring) > 0) {
            if (!polygons[c].rings.empty()) throw std::logic_error("raster_polygons: two outer rings for one component");
            polygons[c].rings.push_back(std::move(ring));
          } else {
            holes[c].push_back(std::move(ring));
          }
        }
      }
    }
    for (std::size_t c = 0; c < polygons.size(); ++c) {
      if (polygons[c].rings.empty()) throw std::logic_error("raster_polygons: a component without outer ring");
      for (auto& hole : holes[c]) polygons[c].rings.push_back(std::move(hole));
    }
    return polygons;
  }

 private:
  // Component of bin (i, j), or -1 outside the raster or for an unlabelled bin.
  int component(int i, int j) const {
    if (i < 0 || j < 0 || i >= nx_ || j >= ny_) return -1;
    return component_[static_cast<std::size_t>(j) * nx_ + i];
  }

  void label_components() {
    component_.assign(labels_.size(), -1);
    std::vector<std::size_t> stack;
    for (std::size_t start = 0; start < labels_.size(); ++start) {
      if (labels_[start] < 0 || component_[start] >= 0) continue;
      const int c = static_cast<int>(component_label_.size());
      const int label = labels_[start];
      component_label_.push_back(label);
      std::size_t count = 0;
      component_[start] = c;
      stack.push_back(start);
      while (!stack.empty()) {
        const std::size_t k = stack.back();
        stack.pop_back();
        ++count;
        const int i = static_cast<int>(k % nx_), j = static_cast<int>(k / nx_);
        for (int d = 0; d < 4; ++d) {
          const int ni = i + kStepI[d], nj = j + kStepJ[d];
          if (ni < 0 || nj < 0 || ni >= nx_ || nj >= ny_) continue;
          const std::size_t n = static_cast<std::size_t>(nj) * nx_ + ni;
          if (labels_[n] == label && component_[n] < 0) {
            component_[n] = c;
            stack.push_back(n);
          }
        }
      }
      component_bins_.push_back(count);
    }
  }

  // Bins left and right of the unit edge leaving corner v in direction d.
  int left_component(GridVertex v, int d) const {
    switch (d) {
      case kEast: return component(v.i, v.j);
      case kNorth: return component(v.i - 1, v.j);
      case kWest: return component(v.i - 1, v.j - 1);
      default: return component(v.i, v.j - 1);
    }
  }
  int right_component(GridVertex v, int d) const {
    switch (d) {
      case kEast: return component(v.i, v.j - 1);
      case kNorth: return component(v.i, v.j);
      case kWest: return component(v.i - 1, v.j);
      default: return component(v.i - 1, v.j - 1);
    }
  }
  bool is_boundary(GridVertex v, int d, int c) const {
    if (v.i < 0 || v.j < 0 || v.i > nx_ || v.j > ny_) return false;
    return left_component(v, d) == c && right_component(v, d) != c;
  }
  std::size_t edge_key(GridVertex v, int d) const {
    return (static_cast<std::size_t>(v.j) * (nx_ + 1) + v.i) * 4 + d;
  }

  // Walks the ring of component c through the edge (start, d0), keeping c on the left. At each
  // corner the first boundary edge among right turn, straight on and left turn is taken. Preferring
  // the right turn matters only where two diagonal bins of c meet at the corner: it joins them
  // there, so the rings on either side of the corner close separately and each stays simple (the
  // component is 4-connected through other bins anyway, or the two bins would not share c).
  GridRing trace(GridVertex start, int d0, int c, bool simplify) {
    GridRing all;
    std::vector<int> out_direction;
    GridVertex v = start;
    int d = d0;
    do {
      visited_[edge_key(v, d)] = true;
      all.push_back(v);
      out_direction.push_back(d);
      v = {v.i + kStepI[d], v.j + kStepJ[d]};
      const int turns[3] = {(d + 3) % 4, d, (d + 1) % 4};
      int next = -1;
      for (const int t : turns) {
        if (is_boundary(v, t, c)) {
          next = t;
          break;
        }
      }
      if (next < 0) throw std::logic_error("raster_polygons: a boundary that does not continue");
      d = next;
    } while (!(v == start && d == d0));

    GridRing ring;
    const std::size_t n = all.size();
    for (std::size_t k = 0; k < n; ++k) {
      // Vertex k is entered along out_direction[k-1] and left along out_direction[k].
      const int in = out_direction[(k + n - 1) % n];
      if (!simplify || in != out_direction[k]) ring.push_back(all[k]);
    }
    ring.push_back(ring.front());
    return ring;
  }

  const std::vector<int>& labels_;
  int nx_;
  int ny_;
  std::vector<int> component_;
  std::vector<int> component_label_;
  std::vector<std::size_t> component_bins_;
  std::vector<bool> visited_;
};

}  // namespace

long long twice_signed_area(const GridRing& ring) {
  long long sum = 0;
  for (std::size_t k = 0; k + 1 < ring.size(); ++k)
    sum += static_cast<long long>(ring[k].i) * ring[k + 1].j - static_cast<long long>(ring[k + 1].i) * ring[k].j;
  return sum;
}

std::vector<GridPolygon> raster_polygons(const std::vector<int>& labels, int nx, int ny, bool simplify_collinear) {
  if (nx < 1 || ny < 1 || labels.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny))
    throw std::invalid_argument("raster_polygons: labels must hold nx * ny >= 1 entries");
  return Tracer(labels, nx, ny).run(simplify_collinear);
}

}  // namespace covmap::mapgen
