// Tracing a raster's regions in two linear passes: label the 4-connected components by an
// explicit-stack flood fill, then scan the pixels row-major and walk every untraced boundary edge
// around its ring with the component on the right ("prefer left" wall following on component
// membership, which is what gives the pinch convention of the header).
#include "gis/pixel_regions.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace covmap::gis {
namespace {

constexpr std::uint32_t kNoComponent = std::numeric_limits<std::uint32_t>::max();

// The direction of a walk along a pixel edge with the pixel on the right. The order is clockwise,
// and walking heading h with pixel p on the right walks p's side number h: top, right, bottom, left.
enum class Heading : std::uint8_t { east, south, west, north };
constexpr std::array kHeadings = {Heading::east, Heading::south, Heading::west, Heading::north};

int index_of(Heading h) { return static_cast<int>(h); }
Heading turned_right(Heading h) { return kHeadings[(index_of(h) + 1) % 4]; }
Heading turned_left(Heading h) { return kHeadings[(index_of(h) + 3) % 4]; }

struct Offset {
  std::int64_t dc = 0, dr = 0;
};
// One pixel (or corner) step in each heading; row grows downwards.
constexpr std::array<Offset, 4> kStep = {{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
// Where the walk along side h of pixel (c, r) ends, relative to corner (c, r).
constexpr std::array<Offset, 4> kEndCorner = {{{1, 0}, {1, 1}, {0, 1}, {0, 0}}};

Offset step(Heading h) { return kStep[index_of(h)]; }

// A directed pixel edge: side `heading` of pixel (col, row), walked with the pixel on the right.
struct Edge {
  std::int64_t col = 0, row = 0;
  Heading heading = Heading::east;
  bool operator==(const Edge&) const = default;
};

PixelCorner end_corner(const Edge& e) {
  const Offset o = kEndCorner[index_of(e.heading)];
  return {e.col + o.dc, e.row + o.dr};
}

void validate(const PixelGrid& grid) {
  const std::string where = "trace_pixel_regions: ";
  if (grid.width < 0 || grid.height < 0)
    throw std::invalid_argument(where + "grid size " + std::to_string(grid.width) + " x " +
                                std::to_string(grid.height) + " is negative; width and height must be >= 0");
  const std::int64_t pixels = std::int64_t{grid.width} * grid.height;
  if (pixels > kMaxPixels)
    throw std::invalid_argument(where + "grid of " + std::to_string(pixels) + " pixels is larger than the " +
                                std::to_string(kMaxPixels) + " supported");
  if (static_cast<std::int64_t>(grid.values.size()) != pixels)
    throw std::invalid_argument(where + "grid has " + std::to_string(grid.values.size()) + " values but width " +
                                std::to_string(grid.width) + " x height " + std::to_string(grid.height) + " = " +
                                std::to_string(pixels) + " pixels; give exactly one value per pixel, row-major");
}

// The 4-connected components of equal values (nodata excluded), numbered in row-major order of
// their first pixel.
struct Components {
  std::vector<std::uint32_t> of_pixel;  // kNoComponent for nodata
  std::vector<std::int64_t> value;      // per component
};

class ComponentLabeller {
 public:
  explicit ComponentLabeller(const PixelGrid& grid) : grid_(grid) {
    result_.of_pixel.assign(grid.values.size(), kNoComponent);
  }

  Components run() && {
    for (std::size_t p = 0; p < grid_.values.size(); ++p)
      if (result_.of_pixel[p] == kNoComponent && !is_nodata(grid_.values[p])) flood(p);
    return std::move(result_);
  }

 private:
  // Depth-first with an explicit stack: a component of 10^8 pixels must not overflow the call stack.
  void flood(std::size_t seed) {
    const auto id = static_cast<std::uint32_t>(result_.value.size());
    const std::int64_t value = grid_.values[seed];
    result_.value.push_back(value);
    claim(seed, id);
    while (!stack_.empty()) {
      const std::size_t p = stack_.back();
      stack_.pop_back();
      const auto col = static_cast<std::int64_t>(p % static_cast<std::size_t>(grid_.width));
      const auto row = static_cast<std::int64_t>(p / static_cast<std::size_t>(grid_.width));
      for (const Offset& o : kStep) {
        const std::int64_t c = col + o.dc, r = row + o.dr;
        if (c < 0 || r < 0 || c >= grid_.width || r >= grid_.height) continue;
        const auto q = static_cast<std::size_t>(r * grid_.width + c);
        if (result_.of_pixel[q] == kNoComponent && grid_.values[q] == value) claim(q, id);
      }
    }
  }
  bool is_nodata(std::int64_t value) const { return grid_.nodata && value == *grid_.nodata; }
  void claim(std::size_t p, std::uint32_t id) {
    result_.of_pixel[p] = id;
    stack_.push_back(static_cast<std::uint32_t>(p));
  }

  const PixelGrid& grid_;
  Components result_;
  std::vector<std::uint32_t> stack_;  // pixel indices fit: at most kMaxPixels pixels
};

// Walks rings and remembers which directed edges it has walked (4 bits per pixel).
class RingTracer {
 public:
  RingTracer(int width, int height, const std::vector<std::uint32_t>& component)
      : width_(width), height_(height), component_(component), traced_(component.size(), 0) {}

  // Side h of the pixel is on the boundary of its component and not yet on a traced ring.
  bool starts_new_ring(const Edge& e) const {
    const Offset out = step(turned_left(e.heading));  // the neighbour across the side
    return !traced(e) && component_at(e.col + out.dc, e.row + out.dr) != component_at(e.col, e.row);
  }

  PixelRing trace(const Edge& start) {
    PixelRing ring;
    Edge e = start;
    do {
      traced_[index(e.col, e.row)] |= bit(e);
      const Edge n = next(e);
      if (n.heading != e.heading) ring.push_back(end_corner(e));
      e = n;
    } while (!(e == start));
    start_at_smallest_corner(ring);
    return ring;
  }

 private:
  // At the end corner of e: turn left if the pixel ahead on the left is in the component, else go
  // straight if the pixel ahead on the right is, else turn right. Checking the left one first is
  // the pinch convention: a diagonal pixel of the same component is joined, one of another
  // component is not.
  Edge next(const Edge& e) const {
    const std::uint32_t own = component_at(e.col, e.row);
    const Offset ahead = step(e.heading), left = step(turned_left(e.heading));
    const std::int64_t rc = e.col + ahead.dc, rr = e.row + ahead.dr;
    const std::int64_t lc = rc + left.dc, lr = rr + left.dr;
    if (component_at(lc, lr) == own) return {lc, lr, turned_left(e.heading)};
    if (component_at(rc, rr) == own) return {rc, rr, e.heading};
    return {e.col, e.row, turned_right(e.heading)};
  }

  static void start_at_smallest_corner(PixelRing& ring) {
    const auto first = std::min_element(ring.begin(), ring.end(), [](const PixelCorner& a, const PixelCorner& b) {
      return std::pair(a.row, a.col) < std::pair(b.row, b.col);
    });
    std::rotate(ring.begin(), first, ring.end());
  }

  std::uint32_t component_at(std::int64_t col, std::int64_t row) const {
    if (col < 0 || row < 0 || col >= width_ || row >= height_) return kNoComponent;
    return component_[index(col, row)];
  }
  std::size_t index(std::int64_t col, std::int64_t row) const { return static_cast<std::size_t>(row * width_ + col); }
  static std::uint8_t bit(const Edge& e) { return static_cast<std::uint8_t>(1u << index_of(e.heading)); }
  bool traced(const Edge& e) const { return (traced_[index(e.col, e.row)] & bit(e)) != 0; }

  std::int64_t width_, height_;
  const std::vector<std::uint32_t>& component_;
  std::vector<std::uint8_t> traced_;
};

// Each component's rings, by component id. The first ring traced for a component is its outer
// ring: the component's first pixel in row-major order is reached before any other of its pixels,
// and its top side, tried first, faces rows free of the component, hence the outside.
std::vector<PixelPolygon> trace_components(const PixelGrid& grid, const Components& components) {
  std::vector<PixelPolygon> polygons(components.value.size());
  RingTracer tracer(grid.width, grid.height, components.of_pixel);
  std::size_t p = 0;
  for (std::int64_t row = 0; row < grid.height; ++row)
    for (std::int64_t col = 0; col < grid.width; ++col, ++p) {
      if (components.of_pixel[p] == kNoComponent) continue;
      PixelPolygon& polygon = polygons[components.of_pixel[p]];
      for (const Heading h : kHeadings) {
        const Edge side{col, row, h};
        if (!tracer.starts_new_ring(side)) continue;
        PixelRing ring = tracer.trace(side);
        if (polygon.outer.empty())
          polygon.outer = std::move(ring);
        else
          polygon.holes.push_back(std::move(ring));
      }
    }
  return polygons;
}

// Component ids are in row-major order of first pixels, so appending keeps that order per value.
std::vector<PixelRegions> group_by_value(const std::vector<std::int64_t>& value_of, std::vector<PixelPolygon> polygons) {
  std::unordered_map<std::int64_t, std::size_t> group_of_value;
  std::vector<PixelRegions> groups;
  for (std::size_t id = 0; id < polygons.size(); ++id) {
    const auto [it, added] = group_of_value.try_emplace(value_of[id], groups.size());
    if (added) groups.push_back({value_of[id], {}});
    groups[it->second].polygons.push_back(std::move(polygons[id]));
  }
  std::sort(groups.begin(), groups.end(), [](const PixelRegions& a, const PixelRegions& b) { return a.value < b.value; });
  return groups;
}

}  // namespace

std::vector<PixelRegions> trace_pixel_regions(const PixelGrid& grid) {
  validate(grid);
  const Components components = ComponentLabeller(grid).run();
  return group_by_value(components.value, trace_components(grid, components));
}

}  // namespace covmap::gis
