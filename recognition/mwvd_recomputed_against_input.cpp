// The MWVD check, half 2 (mwvd_check.h): every arc of the recomputed diagram D has a counterpart
// in the input G — an arc between the same two sites through its midpoint — unless it is shorter
// than its end nodes' conditioning; a face of D without any counterpart is a face G lacks.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/extent.h"
#include "core/point_in_polygon.h"
#include "core/weighted_owner.h"
#include "recognition/mwvd_check.h"
#include "voronoi/arc_path.h"

namespace covmap::recognition::mwvd {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

long long pair_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return static_cast<long long>(a) * 4000000007LL + b;
}

// grad (|p − a|/w_a − |p − b|/w_b): how fast the residual grows across the bisector.
Point residual_gradient(Point p, const Site& a, const Site& b) {
  Point g{0.0, 0.0};
  for (const auto& [s, sign] : {std::pair<const Site*, double>{&a, 1.0}, {&b, -1.0}}) {
    const double dx = p.x - s->x, dy = p.y - s->y, l = std::hypot(dx, dy);
    if (l > 0) g.x += sign * dx / (l * s->weight), g.y += sign * dy / (l * s->weight);
  }
  return g;
}

// One constraint on a node's position: a curve through it (a bisector of two sites, or an exact
// frame edge) as the gradient of its defining function and the uncertainty of that function there.
struct NodeCurve {
  Point gradient;
  double uncertainty = 0.0;
};

// How far a node of D can move when the sites move by τ·scale and the weights by a relative τ:
// for two of its curves, Cramer's rule bounds the displacement by (a₁|g₂| + a₂|g₁|) / |g₁ × g₂|;
// the best-conditioned pair fixes the node, so the smallest bound counts (infinite when its
// curves are all tangent there: a node that any error moves anywhere along them).
double node_conditioning(Point p, const std::vector<NodeCurve>& curves) {
  double best = INFINITY;
  for (std::size_t i = 0; i < curves.size(); ++i)
    for (std::size_t j = i + 1; j < curves.size(); ++j) {
      const Point g1 = curves[i].gradient, g2 = curves[j].gradient;
      const double det = std::abs(g1.x * g2.y - g1.y * g2.x);
      const double num = curves[i].uncertainty * std::hypot(g2.x, g2.y) + curves[j].uncertainty * std::hypot(g1.x, g1.y);
      if (det > 0) best = std::min(best, num / det);
    }
  return std::max(best, kEps * (std::abs(p.x) + std::abs(p.y)));
}

NodeCurve curve_at(const Diagram& d, const Arc& arc, Point p, const Allowance& allowance) {
  if (arc.frame) {  // the frame is exact: its normal, no uncertainty
    const voronoi::ArcPathView path = voronoi::arc_path(arc, d.nodes);
    const Point t = path.tangent(path.param_of(p));
    return {{-t.y, t.x}, 0.0};
  }
  const Site& a = d.sites[arc.left_site];
  const Site& b = d.sites[arc.right_site];
  const double magnitude = std::abs(p.x) + std::abs(p.y);
  return {residual_gradient(p, a, b), allowance.residual(arc.left_site, weighted_distance(p, a), arc.right_site,
                                                         weighted_distance(p, b), magnitude)};
}

std::vector<double> conditioning_of_nodes(const Diagram& d, const Allowance& allowance) {
  std::vector<std::vector<int>> at(d.nodes.size());
  for (std::size_t a = 0; a < d.arcs.size(); ++a)
    for (int v : {d.arcs[a].from, d.arcs[a].to})
      if (v != kNone) at[v].push_back(static_cast<int>(a));
  std::vector<double> kappa(d.nodes.size(), 0.0);
  for (std::size_t v = 0; v < d.nodes.size(); ++v) {
    const Point p{d.nodes[v].x, d.nodes[v].y};
    std::vector<NodeCurve> curves;
    for (int a : at[v]) {
      const Arc& arc = d.arcs[a];
      if (!arc.frame && (arc.left_site == kNone || arc.right_site == kNone)) continue;
      curves.push_back(curve_at(d, arc, p, allowance));
    }
    kappa[v] = node_conditioning(p, curves);
  }
  return kappa;
}

double arc_length(const voronoi::ArcPathView& p) {
  const double s = p.s1 - p.s0;
  return p.circle ? p.r * s : s;
}

Point midpoint(const voronoi::ArcPathView& p, double scale) {
  if (std::isfinite(p.s0) && std::isfinite(p.s1)) return p.at(0.5 * (p.s0 + p.s1));
  if (std::isfinite(p.s0)) return p.at(p.s0 + scale);
  if (std::isfinite(p.s1)) return p.at(p.s1 - scale);
  return p.at(p.param_of({p.ox, p.oy}));
}

double distance_to_arc(const voronoi::ArcPathView& p, Point q) {
  const double s = p.param_of(q);
  if (p.circle && s > p.s1) {
    const Point e0 = p.at(p.s0), e1 = p.at(p.s1);
    return std::min(std::hypot(q.x - e0.x, q.y - e0.y), std::hypot(q.x - e1.x, q.y - e1.y));
  }
  const Point on = p.at(p.circle ? s : std::clamp(s, p.s0, p.s1));
  return std::hypot(q.x - on.x, q.y - on.y);
}

// Whether a site other than a and b is, at m, within the allowance of being as close as they are:
// then m is within the conditioning of a node, and whether the a–b arc passes there is not decided
// by the sites' accuracy. The less certain of a and b (the larger spread) is the one compared: m
// is on their bisector, and it is that site's uncertainty that moves the arc.
bool third_site_as_close(Point m, int a, int b, const Sites& s, const Allowance& allowance) {
  if (allowance.spread[b] > allowance.spread[a]) std::swap(a, b);
  const double da = weighted_distance(m, s.sites[a]), magnitude = std::abs(m.x) + std::abs(m.y);
  // residual(a, k) ≤ c + τ·spread_k·dk ≤ c + τ·widest·dk for every site k, so a site within it has
  // dk ≤ (da + c) / (1 − τ·widest): the query's bound (none when sites may move by half an extent).
  const double c = allowance.residual_bound(a, da, magnitude, s.smallest_weight);
  const double shrink = 1 - allowance.tau * allowance.widest_spread;
  const double bound = shrink > 0.5 ? (da + c) / shrink : INFINITY;
  bool found = false;
  s.index.for_each_closer(m, std::nextafter(bound, INFINITY), [&](int k, double dk) {
    if (k == a || k == b) return true;
    found = dk - da <= allowance.residual(a, da, k, dk, magnitude);
    return !found;
  });
  return found;
}

// What each arc of D is: tiny (no evidence either way), matched in G, or missing from G.
enum class Evidence { kTiny, kMatched, kMissing };

// A point to name a missing face by: the centre of its outer boundary's sample points when that
// lies inside them (bounded faces), else the midpoint of its longest arc.
Point point_of_face(const Diagram& d, const Face& face, const std::vector<voronoi::ArcPathView>& paths, double scale) {
  if (face_cycles(d, face).empty()) return {};
  std::vector<Point> ring;
  Point longest{};
  double longest_length = -1;
  for (const HalfArc& h : face_cycles(d, face).front()) {
    const auto& p = paths[h.arc];
    const double length = arc_length(p);
    if (length > longest_length) longest_length = length, longest = midpoint(p, scale);
    if (!std::isfinite(length)) continue;
    for (int k = 0; k < 16; ++k) ring.push_back(p.at(p.s0 + (k + 0.5) / 16 * (p.s1 - p.s0)));
  }
  if (!face.bounded || ring.empty()) return longest;
  Point c{0, 0};
  for (const Point& q : ring) c.x += q.x / ring.size(), c.y += q.y / ring.size();
  return inside_ring(ring, c) ? c : longest;
}

}  // namespace

std::vector<Difference> recomputed_against_input(const Diagram& d, const Diagram& g, const std::vector<ArcSites>& labels,
                                                 const Sites& s, const Allowance& allowance) {
  const std::vector<Site>& sites = s.sites;
  // G's arcs by the pair of sites they separate, sorted by it (one flat array: 10^6-site graphs).
  std::vector<std::pair<long long, int>> g_arcs;
  for (std::size_t a = 0; a < g.arcs.size(); ++a)
    if (labels[a].left != kNone && labels[a].right != kNone)
      g_arcs.emplace_back(pair_key(labels[a].left, labels[a].right), static_cast<int>(a));
  std::sort(g_arcs.begin(), g_arcs.end());
  const std::vector<double> kappa = conditioning_of_nodes(d, allowance);
  std::vector<voronoi::ArcPathView> paths;
  paths.reserve(d.arcs.size());
  for (const Arc& arc : d.arcs) paths.push_back(voronoi::arc_path(arc, d.nodes));

  std::vector<Evidence> evidence(d.arcs.size(), Evidence::kTiny);
  for (std::size_t j = 0; j < d.arcs.size(); ++j) {
    const Arc& arc = d.arcs[j];
    if (arc.frame || arc.left_site == kNone || arc.right_site == kNone) continue;
    const double moves = (arc.from == kNone ? 0.0 : kappa[arc.from]) + (arc.to == kNone ? 0.0 : kappa[arc.to]);
    if (!(arc_length(paths[j]) > 2 * moves)) continue;  // its ends can move past its midpoint
    const Point m = midpoint(paths[j], allowance.scale);
    const Site& a = sites[arc.left_site];
    const Site& b = sites[arc.right_site];
    if (third_site_as_close(m, arc.left_site, arc.right_site, s, allowance)) continue;
    const Point grad = residual_gradient(m, a, b);
    const double across = allowance.residual(arc.left_site, weighted_distance(m, a), arc.right_site,
                                             weighted_distance(m, b), std::abs(m.x) + std::abs(m.y)) /
                          std::hypot(grad.x, grad.y);
    // An arc that may move across by more than its distance from its sites may pass on either side
    // of them: the sites are not told apart at their accuracy (two sites the reconstruction kept for
    // one region of the input, a far orphan's fixed only by its huge circles), and the arc says
    // nothing.
    if (!(across < std::min(std::hypot(m.x - a.x, m.y - a.y), std::hypot(m.x - b.x, m.y - b.y)))) continue;
    evidence[j] = Evidence::kMissing;
    const long long key = pair_key(arc.left_site, arc.right_site);
    const auto first = std::lower_bound(g_arcs.begin(), g_arcs.end(), std::pair<long long, int>{key, -1});
    for (auto it = first; it != g_arcs.end() && it->first == key; ++it)
      if (distance_to_arc(voronoi::arc_path(g.arcs[it->second], g.nodes), m) <=
          across + allowance.stated_curve(g.arcs[it->second], m)) {
        evidence[j] = Evidence::kMatched;
        break;
      }
  }

  // Faces of D none of whose (non-tiny) arcs G has: missing faces; their arcs are not listed again.
  std::vector<Difference> out;
  std::vector<char> in_missing_face(d.arcs.size(), 0);
  for (std::size_t f = 0; f < d.faces.size(); ++f) {
    const Face& face = d.faces[f];
    bool any = false, matched = false;
    for (const auto cycle : face_cycles(d, face))
      for (const HalfArc& h : cycle) {
        any = any || evidence[h.arc] != Evidence::kTiny;
        matched = matched || evidence[h.arc] == Evidence::kMatched;
      }
    if (!any || matched || face.site == kNone) continue;
    for (const auto cycle : face_cycles(d, face))
      for (const HalfArc& h : cycle) in_missing_face[h.arc] = 1;
    const Point p = point_of_face(d, face, paths, allowance.scale);
    std::ostringstream msg;
    msg << (face.orphan ? "orphan face" : "face") << " of site '" << sites[face.site].id << "' around (" << p.x
        << ", " << p.y << ") is missing from the input";
    out.push_back({DifferenceKind::FaceOnlyInB, static_cast<int>(f), p.x, p.y, msg.str()});
  }
  for (std::size_t j = 0; j < d.arcs.size(); ++j) {
    if (evidence[j] != Evidence::kMissing || in_missing_face[j]) continue;
    const Point m = midpoint(paths[j], allowance.scale);
    std::ostringstream msg;
    msg << "arc " << j << " near (" << m.x << ", " << m.y << ") between the regions of sites '"
        << sites[d.arcs[j].left_site].id << "' and '" << sites[d.arcs[j].right_site].id
        << "' has no counterpart in the input";
    out.push_back({DifferenceKind::ArcOnlyInB, static_cast<int>(j), m.x, m.y, msg.str()});
  }
  return out;
}

}  // namespace covmap::recognition::mwvd
