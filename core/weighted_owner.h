// Brute-force-exact weighted ownership: which site minimises |p - s| / w.
//
// The checker's ground truth (check/), and the nearest-site queries of recognition's MWVD check
// (recognition/mwvd_check.cpp). It lives in core, apart from the engine, so that the checker still
// shares no code with what it checks. The answer is exactly that of a linear scan over all sites (same
// floating-point distances, same tie-break by smallest index); a kd-tree only skips subtrees that
// provably cannot win, using the lower bound dist(p, box) / max weight in the box. Sites with
// non-finite data or weight <= 0 are left out (the caller reports them).
#pragma once

#include <functional>
#include <vector>

#include "core/diagram.h"

namespace covmap {

// |p - s| / w.
double weighted_distance(Point p, const Site& s);

// Signed first-order distance (a length) from p to the weighted bisector of a and b:
// (d_a - d_b) / |grad(d_a - d_b)|. Negative when a is weighted-closer. Exact to first order near
// the bisector, which is where tolerances are decided; +-infinity where the gradient vanishes
// (equal weights, p on the line through both sites outside the segment: far from the bisector
// anyway).
double bisector_offset(Point p, const Site& a, const Site& b);

bool site_is_valid(const Site& s);

class WeightedSiteIndex {
 public:
  explicit WeightedSiteIndex(const std::vector<Site>& sites);

  // The valid site with the smallest weighted distance to p (smallest index among exact ties);
  // kNone when there is no valid site.
  int nearest(Point p) const;

  // Calls visit(site, weighted distance) for valid sites with weighted distance < bound, in no
  // particular order, until visit returns false.
  void for_each_closer(Point p, double bound, const std::function<bool(int, double)>& visit) const;

 private:
  struct KdNode {
    double xmin, ymin, xmax, ymax;
    double wmax;
    int begin, end;           // range in order_
    int low = -1, high = -1;  // children; -1 for leaves
  };
  int build(int begin, int end);
  double lower_bound(const KdNode& n, Point p) const;
  void nearest_in(int node, Point p, int* best, double* best_d) const;

  std::vector<double> xs_, ys_, ws_;  // per site; only valid sites appear in order_
  std::vector<int> order_;
  std::vector<KdNode> nodes_;
  int root_ = -1;
};

}  // namespace covmap
