// The MWVD check, half 1 (mwvd_check.h): the input's nodes and arc samples against the
// reconstructed sites — equidistant to their own sites, no other site closer, each within the
// allowance of the point's own conditioning.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/parallel.h"
#include "core/weighted_owner.h"
#include "recognition/mwvd_check.h"
#include "recognition/tolerances.h"
#include "voronoi/arc_path.h"

namespace covmap::recognition::mwvd {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Interior sample points per arc (the nodes are tested on their own): a wrong arc between two
// right nodes bends away from the bisector most in its middle.
constexpr int kSamplesPerArc = 3;

enum class Defect { kNone, kNotEquidistant, kCloserSite };

// The worst violation at one point: how many allowances it exceeds, and which sites.
struct Finding {
  Defect defect = Defect::kNone;
  double excess = 0.0;   // the residual in units of its allowance (> 1 fails)
  double residual = 0.0; // the difference of weighted distances
  int own = kNone;       // the own site involved
  int other = kNone;     // the other own site (not equidistant) or the closer site
  Point at;
};

// Tests point p against its own sites (those of the faces it bounds).
Finding test_point(Point p, std::span<const int> own, const std::vector<Site>& sites, const WeightedSiteIndex& index,
                   const Allowance& allowance, double magnitude, double moved = 0.0) {
  Finding f;
  f.at = p;
  int nearest = kNone, farthest = kNone;
  double dn = INFINITY, df = -INFINITY;
  for (int k : own) {
    const double d = weighted_distance(p, sites[k]);
    if (d < dn) dn = d, nearest = k;
    if (d > df) df = d, farthest = k;
  }
  if (nearest == kNone) return f;
  if (farthest != nearest) {
    const double excess = (df - dn) / allowance.residual(nearest, dn, farthest, df, magnitude, moved);
    if (excess > 1.0) f = {Defect::kNotEquidistant, excess, df - dn, nearest, farthest, p};
  }
  // The own site compared with a closer one is the least certain (largest spread): the own sites
  // are equidistant at p, and it is that one's uncertainty that moves the point.
  int loosest = nearest;
  for (int k : own)
    if (allowance.spread[k] > allowance.spread[loosest]) loosest = k;
  index.for_each_closer(p, dn, [&](int k, double dk) {
    if (std::find(own.begin(), own.end(), k) != own.end()) return true;
    const double excess = (dn - dk) / allowance.residual(loosest, dn, k, dk, magnitude, moved);
    if (excess > 1.0 && excess > f.excess) f = {Defect::kCloserSite, excess, dn - dk, nearest, k, p};
    return true;
  });
  return f;
}

std::string describe(const Finding& f, const std::vector<Site>& sites) {
  std::ostringstream m;
  if (f.defect == Defect::kCloserSite)
    m << "site '" << sites[f.other].id << "' is closer than site '" << sites[f.own].id << "'";
  else
    m << "not equidistant to sites '" << sites[f.own].id << "' and '" << sites[f.other].id << "'";
  m << " (weighted distances differ by " << f.residual << ", " << f.excess << " times the allowance)";
  return m.str();
}

// The sites around every node (those on the sides of its arcs), in compressed rows.
struct NodeSites {
  std::vector<int> begin;  // per node, plus one
  std::vector<int> site;
};

NodeSites node_sites(const Diagram& g, const std::vector<ArcSites>& labels) {
  NodeSites out;
  out.begin.assign(g.nodes.size() + 1, 0);
  for (const Arc& a : g.arcs)
    for (int v : {a.from, a.to})
      if (v != kNone) out.begin[v + 1] += 2;
  for (std::size_t v = 0; v < g.nodes.size(); ++v) out.begin[v + 1] += out.begin[v];
  out.site.assign(out.begin.back(), kNone);
  std::vector<int> fill(out.begin.begin(), out.begin.end() - 1);
  for (std::size_t a = 0; a < g.arcs.size(); ++a)
    for (int v : {g.arcs[a].from, g.arcs[a].to}) {
      if (v == kNone) continue;
      out.site[fill[v]++] = labels[a].left;
      out.site[fill[v]++] = labels[a].right;
    }
  return out;
}

// The distinct assigned sites of one node.
std::vector<int> own_sites(const NodeSites& ns, std::size_t v) {
  std::vector<int> own;
  for (int k = ns.begin[v]; k < ns.begin[v + 1]; ++k)
    if (ns.site[k] != kNone && std::find(own.begin(), own.end(), ns.site[k]) == own.end()) own.push_back(ns.site[k]);
  return own;
}

// Parameters of the sample points of an arc: inside a bounded arc; along the finite stretch of an
// unbounded line next to its end, or around the point nearest the centre for a whole line.
std::vector<double> sample_parameters(const voronoi::ArcPathView& p, Point centre, double scale) {
  std::vector<double> s;
  for (int k = 1; k <= kSamplesPerArc; ++k) {
    const double t = static_cast<double>(k) / (kSamplesPerArc + 1);
    if (std::isfinite(p.s0) && std::isfinite(p.s1)) {
      if (p.s1 > p.s0) s.push_back(p.s0 + t * (p.s1 - p.s0));
    } else if (std::isfinite(p.s0)) {
      s.push_back(p.s0 + 2 * t * scale);
    } else if (std::isfinite(p.s1)) {
      s.push_back(p.s1 - 2 * t * scale);
    } else {
      s.push_back(p.param_of(centre) + (2 * t - 1) * scale);
    }
  }
  return s;
}

double curve_magnitude(const Arc& a) {
  if (const auto* c = std::get_if<Circle>(&a.curve)) return std::abs(c->cx) + std::abs(c->cy) + c->r;
  const auto& l = std::get<Line>(a.curve);
  return std::abs(l.x) + std::abs(l.y);
}

// Runs test(i, out) for i in [0, n) on the workers; the differences come out in index order.
template <class Test>
std::vector<Difference> in_order(std::size_t n, Test&& test) {
  const int workers = worker_count(n);
  std::vector<std::vector<Difference>> found(workers);
  parallel_chunks(n, workers, [&](std::size_t b, std::size_t e, int w) {
    for (std::size_t i = b; i < e; ++i) test(i, found[w]);
  });
  std::vector<Difference> out;
  for (auto& f : found) out.insert(out.end(), f.begin(), f.end());
  return out;
}

}  // namespace

double Allowance::residual(int a, double da, int b, double db, double magnitude, double moved) const {
  const double wa = sites[a].weight, wb = sites[b].weight, sa = spread[a], sb = spread[b];
  const double rounding = tolerance::kPointRoundingUlps * kEps * magnitude + moved;
  // 1/w_a + 1/w_b bounds the residual's gradient: how much a moved point changes it.
  return tau * (scale * (sa / wa + sb / wb) + sa * da + sb * db) + rounding * (1.0 / wa + 1.0 / wb);
}

double Allowance::residual_bound(int a, double da, double magnitude, double lightest_weight) const {
  const double wa = sites[a].weight, sa = spread[a];
  const double rounding = tolerance::kPointRoundingUlps * kEps * magnitude;
  return tau * (scale * (sa / wa + widest_spread / lightest_weight) + sa * da) +
         rounding * (1.0 / wa + 1.0 / lightest_weight);
}

double stated_size(const Arc& arc, Point centre, Point p) {
  if (const auto* c = std::get_if<Circle>(&arc.curve)) return std::hypot(c->cx - centre.x, c->cy - centre.y) + c->r;
  const auto& l = std::get<Line>(arc.curve);  // the anchor, and the direction over the lever to p
  return std::hypot(l.x - centre.x, l.y - centre.y) + std::hypot(p.x - l.x, p.y - l.y);
}

double Allowance::stated_curve(const Arc& arc, Point p) const { return tau * stated_size(arc, centre, p); }

std::vector<Difference> input_against_sites(const Diagram& g, const std::vector<ArcSites>& labels, const Sites& s,
                                            const Allowance& allowance) {
  const std::vector<Site>& sites = s.sites;
  const WeightedSiteIndex& index = s.index;
  const NodeSites ns = node_sites(g, labels);
  std::vector<Difference> out = in_order(g.nodes.size(), [&](std::size_t v, std::vector<Difference>& found) {
    const std::vector<int> own = own_sites(ns, v);
    const Point p{g.nodes[v].x, g.nodes[v].y};
    if (own.empty() || !std::isfinite(p.x) || !std::isfinite(p.y)) return;
    const Finding f = test_point(p, own, sites, index, allowance, std::abs(p.x) + std::abs(p.y));
    if (f.defect == Defect::kNone) return;
    std::ostringstream m;
    m << "node " << v << " at (" << p.x << ", " << p.y << "): " << describe(f, sites);
    found.push_back({DifferenceKind::NodeOnlyInA, static_cast<int>(v), p.x, p.y, m.str()});
  });
  std::vector<Difference> arcs = in_order(g.arcs.size(), [&](std::size_t a, std::vector<Difference>& found) {
    const Arc& arc = g.arcs[a];
    std::vector<int> own;
    for (int k : {labels[a].left, labels[a].right})
      if (k != kNone) own.push_back(k);
    if (own.empty()) return;
    const voronoi::ArcPathView path = voronoi::arc_path(arc, g.nodes);
    Finding worst;
    for (double t : sample_parameters(path, allowance.centre, allowance.scale)) {
      const Point p = path.at(t);
      const Finding f = test_point(p, own, sites, index, allowance, curve_magnitude(arc) + std::abs(p.x) + std::abs(p.y),
                                   allowance.stated_curve(arc, p));
      if (f.excess > worst.excess) worst = f;
    }
    if (worst.defect == Defect::kNone) return;
    std::ostringstream m;
    m << "arc " << a << " near (" << worst.at.x << ", " << worst.at.y << "): " << describe(worst, sites);
    found.push_back({DifferenceKind::ArcOnlyInA, static_cast<int>(a), worst.at.x, worst.at.y, m.str()});
  });
  out.insert(out.end(), arcs.begin(), arcs.end());
  return out;
}

}  // namespace covmap::recognition::mwvd
