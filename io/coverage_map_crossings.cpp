#include "io/coverage_map_crossings.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

#include "io/polygon_check.h"

namespace covmap::io::detail {
namespace {


// Grid tuning. These trade speed only; the answer is exact whatever their values.
// Average number of cells a long edge may cover before the cells are enlarged: keeps the
// bucketing linear when a few long edges sit among many short ones.
constexpr double kCellsPerEdge = 4.0;
// Cells per axis at most, so that a cell key (row * columns + column) fits in 64 bits.
constexpr double kMaxCellsPerAxis = static_cast<double>(1 << 26);
// Slack added around every edge before it is bucketed, in units of (unit roundoff x largest
// coordinate magnitude). The cell of a point is computed in floating point; each step of that
// arithmetic (a subtraction, a product by the cell size, a division) errs by at most a few units,
// so 32 units is a comfortable margin: every cell an edge truly touches is among those it is put in,
// hence two edges that meet always share a cell.
constexpr double kRoundoffUnits = 32.0;

struct Edge {
  Point a;
  Point b;
};

bool share_endpoint(const Edge& e, const Edge& f) {
  const auto same = [](Point p, Point q) { return p.x == q.x && p.y == q.y; };
  return same(e.a, f.a) || same(e.a, f.b) || same(e.b, f.a) || same(e.b, f.b);
}

bool boxes_overlap(const Edge& e, const Edge& f) {
  return std::max(std::min(e.a.x, e.b.x), std::min(f.a.x, f.b.x)) <= std::min(std::max(e.a.x, e.b.x), std::max(f.a.x, f.b.x)) &&
         std::max(std::min(e.a.y, e.b.y), std::min(f.a.y, f.b.y)) <= std::min(std::max(e.a.y, e.b.y), std::max(f.a.y, f.b.y));
}

// The sparse grid: which cells each edge may touch, as (cell key, edge index) marks.
class Grid {
 public:
  explicit Grid(const std::vector<Edge>& edges) {
    double xmax = -std::numeric_limits<double>::infinity(), ymax = xmax;
    xmin_ = ymin_ = std::numeric_limits<double>::infinity();
    std::vector<double> lengths;
    lengths.reserve(edges.size());
    for (const Edge& e : edges) {
      xmin_ = std::min({xmin_, e.a.x, e.b.x});
      ymin_ = std::min({ymin_, e.a.y, e.b.y});
      xmax = std::max({xmax, e.a.x, e.b.x});
      ymax = std::max({ymax, e.a.y, e.b.y});
      lengths.push_back(std::hypot(e.b.x - e.a.x, e.b.y - e.a.y));
    }
    const double magnitude = std::max({std::abs(xmin_), std::abs(ymin_), std::abs(xmax), std::abs(ymax)});
    slack_ = kRoundoffUnits * (std::numeric_limits<double>::epsilon() / 2) * magnitude;

    // Cell size: about one edge long, so an edge meets a handful of cells and a cell a handful of
    // edges; but no smaller than the slack (or every edge would smear over many cells).
    const double total = std::accumulate(lengths.begin(), lengths.end(), 0.0);
    auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    const double extent = std::max(xmax - xmin_, ymax - ymin_);
    cell_ = std::max({*middle, total / (kCellsPerEdge * static_cast<double>(edges.size())),
                      extent / (kMaxCellsPerAxis - 2), 4 * slack_});
    if (!(cell_ > 0)) cell_ = 1.0;  // all vertices at one point: a single cell
    columns_ = static_cast<std::uint64_t>((xmax - xmin_) / cell_) + 1;
    rows_ = static_cast<std::uint64_t>((ymax - ymin_) / cell_) + 1;

    for (std::size_t i = 0; i < edges.size(); ++i) mark(edges[i], static_cast<std::uint32_t>(i));
    std::sort(marks_.begin(), marks_.end());
  }

  // (cell key, edge index), sorted: the edges of one cell are a contiguous run in index order.
  const std::vector<std::pair<std::uint64_t, std::uint32_t>>& marks() const { return marks_; }

 private:
  std::uint64_t column(double x) const { return index((x - xmin_) / cell_, columns_); }
  std::uint64_t row(double y) const { return index((y - ymin_) / cell_, rows_); }
  static std::uint64_t index(double t, std::uint64_t count) {
    if (!(t > 0)) return 0;
    return std::min(static_cast<std::uint64_t>(t), count - 1);
  }

  // Marks every cell within `slack_` of the edge: column by column, the rows its y-range spans
  // inside that column's slab (itself widened by the slack).
  void mark(const Edge& e, std::uint32_t id) {
    const double x_lo = std::min(e.a.x, e.b.x), x_hi = std::max(e.a.x, e.b.x);
    const double y_lo = std::min(e.a.y, e.b.y) - slack_, y_hi = std::max(e.a.y, e.b.y) + slack_;
    const bool vertical = e.a.x == e.b.x;
    const double slope = vertical ? 0.0 : (e.b.y - e.a.y) / (e.b.x - e.a.x);
    const auto y_at = [&](double x) { return e.a.y + (x - e.a.x) * slope; };
    const std::uint64_t c_end = column(x_hi + slack_);
    for (std::uint64_t c = column(x_lo - slack_); c <= c_end; ++c) {
      double left = std::max(xmin_ + static_cast<double>(c) * cell_ - slack_, x_lo);
      double right = std::min(xmin_ + static_cast<double>(c + 1) * cell_ + slack_, x_hi);
      if (left > right) left = right = (left > x_hi ? x_hi : x_lo);  // the slab only meets the slack
      double lo = y_lo, hi = y_hi;
      if (!vertical) {
        const double y1 = y_at(left), y2 = y_at(right);
        lo = std::max(std::min(y1, y2) - slack_, y_lo);
        hi = std::min(std::max(y1, y2) + slack_, y_hi);
      }
      const std::uint64_t r_end = row(hi);
      for (std::uint64_t r = row(lo); r <= r_end; ++r) marks_.emplace_back(r * columns_ + c, id);
    }
  }

  double xmin_ = 0.0, ymin_ = 0.0;
  double cell_ = 1.0;
  double slack_ = 0.0;
  std::uint64_t columns_ = 1, rows_ = 1;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> marks_;
};

}  // namespace

bool properly_cross(Point p1, Point p2, Point q1, Point q2) {
  const int o1 = orientation(p1, p2, q1);
  const int o2 = orientation(p1, p2, q2);
  if (o1 == 0 || o2 == 0 || o1 == o2) return false;
  const int o3 = orientation(q1, q2, p1);
  const int o4 = orientation(q1, q2, p2);
  return o3 != 0 && o4 != 0 && o3 != o4;
}

std::optional<Crossing> first_crossing(std::span<const std::vector<Point>> rings) {
  // Edges numbered ring by ring, edge by edge, so index order is EdgeRef order.
  std::vector<Edge> edges;
  std::vector<EdgeRef> refs;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
      refs.push_back({r, i});
    }
  }
  if (edges.size() < 4) return std::nullopt;  // a triangle cannot cross itself

  const Grid grid(edges);
  const auto& marks = grid.marks();
  constexpr auto kNoEdge = std::numeric_limits<std::uint32_t>::max();
  std::pair<std::uint32_t, std::uint32_t> best{kNoEdge, kNoEdge};
  for (std::size_t start = 0; start < marks.size();) {
    std::size_t end = start + 1;
    while (end < marks.size() && marks[end].first == marks[start].first) ++end;
    for (std::size_t i = start; i < end; ++i) {
      const std::uint32_t e = marks[i].second;
      if (e > best.first) break;  // later edges in this cell have larger indices still
      for (std::size_t j = i + 1; j < end; ++j) {
        const std::uint32_t f = marks[j].second;
        if (e == f || std::pair(e, f) >= best) continue;
        if (!boxes_overlap(edges[e], edges[f]) || share_endpoint(edges[e], edges[f])) continue;
        if (properly_cross(edges[e].a, edges[e].b, edges[f].a, edges[f].b)) best = {e, f};
      }
    }
    start = end;
  }
  if (best.first == kNoEdge) return std::nullopt;
  return Crossing{refs[best.first], refs[best.second]};
}

}  // namespace covmap::io::detail
