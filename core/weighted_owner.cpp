#include "core/weighted_owner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace covmap {
namespace {
constexpr int kLeafSize = 8;
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

double weighted_distance(Point p, const Site& s) {
  const double dx = p.x - s.x, dy = p.y - s.y;
  return std::sqrt(dx * dx + dy * dy) / s.weight;
}

double bisector_offset(Point p, const Site& a, const Site& b) {
  const double ax = p.x - a.x, ay = p.y - a.y, bx = p.x - b.x, by = p.y - b.y;
  const double la = std::sqrt(ax * ax + ay * ay), lb = std::sqrt(bx * bx + by * by);
  // f = la / wa - lb / wb, rearranged so that far from the sites (la, lb >> |b - a|, where nearly
  // equal weights put nodes) nothing cancels: la - lb = (la^2 - lb^2) / (la + lb) with
  // la^2 - lb^2 = (b - a).(2p - a - b), and f = (la - lb) / wa + lb (wb - wa) / (wa wb).
  const double sum = la + lb;
  const double la_minus_lb =
      sum > 0.0 ? ((b.x - a.x) * (ax + bx) + (b.y - a.y) * (ay + by)) / sum : 0.0;
  const double f = la_minus_lb / a.weight + lb * (b.weight - a.weight) / (a.weight * b.weight);
  // grad f = unit(p - a) / wa - unit(p - b) / wb; at p == s take the zero subgradient. Far out the
  // two unit vectors agree to ~|b - a| / |p|, and subtracting them as computed left rounding (or 0:
  // "inf off" at the nodes 1e15 out of nearly collinear sites). With d = b - a and p - b = (p - a) - d:
  //   grad f = (p - a) (la (wb - wa) - wb (la - lb)) / (la lb wa wb) + d / (lb wb),
  // where la - lb is the cancellation-free difference above, and the two terms cancel only where
  // the gradient truly vanishes (p on the line through both sites).
  double gx = 0.0, gy = 0.0;
  if (la > 0.0 && lb > 0.0) {
    const double k = (la * (b.weight - a.weight) - b.weight * la_minus_lb) / (la * lb * a.weight * b.weight);
    gx = ax * k + (b.x - a.x) / (lb * b.weight);
    gy = ay * k + (b.y - a.y) / (lb * b.weight);
  } else if (la > 0.0) {
    gx = ax / (la * a.weight), gy = ay / (la * a.weight);
  } else if (lb > 0.0) {
    gx = -bx / (lb * b.weight), gy = -by / (lb * b.weight);
  }
  const double g = std::sqrt(gx * gx + gy * gy);
  if (g == 0.0) return f == 0.0 ? 0.0 : std::copysign(kInf, f);
  return f / g;
}

bool site_is_valid(const Site& s) {
  return std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.weight) && s.weight > 0.0;
}

WeightedSiteIndex::WeightedSiteIndex(const std::vector<Site>& sites) {
  xs_.reserve(sites.size());
  ys_.reserve(sites.size());
  ws_.reserve(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) {
    xs_.push_back(sites[i].x);
    ys_.push_back(sites[i].y);
    ws_.push_back(sites[i].weight);
    if (site_is_valid(sites[i])) order_.push_back(static_cast<int>(i));
  }
  if (!order_.empty()) {
    nodes_.reserve(2 * order_.size() / kLeafSize + 2);
    root_ = build(0, static_cast<int>(order_.size()));
  }
}

int WeightedSiteIndex::build(int begin, int end) {
  KdNode n{kInf, kInf, -kInf, -kInf, 0.0, begin, end};
  for (int k = begin; k < end; ++k) {
    const int i = order_[k];
    n.xmin = std::min(n.xmin, xs_[i]);
    n.xmax = std::max(n.xmax, xs_[i]);
    n.ymin = std::min(n.ymin, ys_[i]);
    n.ymax = std::max(n.ymax, ys_[i]);
    n.wmax = std::max(n.wmax, ws_[i]);
  }
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(n);
  if (end - begin <= kLeafSize) return id;
  const bool split_x = (n.xmax - n.xmin) >= (n.ymax - n.ymin);
  const int mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) { return split_x ? xs_[a] < xs_[b] : ys_[a] < ys_[b]; });
  const int low = build(begin, mid);
  const int high = build(mid, end);
  nodes_[id].low = low;
  nodes_[id].high = high;
  return id;
}

double WeightedSiteIndex::lower_bound(const KdNode& n, Point p) const {
  const double dx = std::max({n.xmin - p.x, 0.0, p.x - n.xmax});
  const double dy = std::max({n.ymin - p.y, 0.0, p.y - n.ymax});
  return std::sqrt(dx * dx + dy * dy) / n.wmax;
}

void WeightedSiteIndex::nearest_in(int node, Point p, int* best, double* best_d) const {
  const KdNode& n = nodes_[node];
  // ">" rather than ">=": a subtree that can only tie may still hold a smaller index.
  if (lower_bound(n, p) > *best_d) return;
  if (n.low < 0) {
    for (int k = n.begin; k < n.end; ++k) {
      const int i = order_[k];
      const double dx = p.x - xs_[i], dy = p.y - ys_[i];
      const double d = std::sqrt(dx * dx + dy * dy) / ws_[i];
      if (d < *best_d || (d == *best_d && i < *best)) {
        *best_d = d;
        *best = i;
      }
    }
    return;
  }
  int first = n.low, second = n.high;
  if (lower_bound(nodes_[second], p) < lower_bound(nodes_[first], p)) std::swap(first, second);
  nearest_in(first, p, best, best_d);
  nearest_in(second, p, best, best_d);
}

int WeightedSiteIndex::nearest(Point p) const {
  if (root_ < 0) return kNone;
  int best = kNone;
  double best_d = kInf;
  nearest_in(root_, p, &best, &best_d);
  return best;
}

void WeightedSiteIndex::for_each_closer(Point p, double bound,
                                        const std::function<bool(int, double)>& visit) const {
  if (root_ < 0) return;
  // Median splits keep the depth below 64, and a depth-first stack never holds more than depth + 1
  // entries; a fixed array avoids an allocation per query (millions of queries on large diagrams).
  std::array<int, 128> stack{};
  int top = 0;
  stack[top++] = root_;
  while (top > 0) {
    const KdNode& n = nodes_[stack[--top]];
    if (lower_bound(n, p) >= bound) continue;
    if (n.low >= 0) {
      stack[top++] = n.low;
      stack[top++] = n.high;
      continue;
    }
    for (int k = n.begin; k < n.end; ++k) {
      const int i = order_[k];
      const double dx = p.x - xs_[i], dy = p.y - ys_[i];
      const double d = std::sqrt(dx * dx + dy * dy) / ws_[i];
      if (d < bound && !visit(i, d)) return;
    }
  }
}

}  // namespace covmap
