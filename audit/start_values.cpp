#include "audit/start_values.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>

#include "mobius/bisector_relation.h"
#include "mobius/node_constraint.h"
#include "audit/tolerances.h"
#include "core/parallel.h"
#include "voronoi/arc_path.h"

namespace covmap::audit {
namespace {


struct SiteConstraint {
  bool circle = true;
  mobius::Complex centre;  // circle centre, or the point
  double radius = 0.0;
};

mobius::GeneralizedCircle plane_curve(const Arc& a) {
  if (const auto* c = std::get_if<Circle>(&a.curve)) return mobius::GeneralizedCircle::from(*c);
  return mobius::GeneralizedCircle::from(std::get<Line>(a.curve));
}

// The arcs at each node, in counter-clockwise order of their leaving direction, with the sensor in
// the sector that follows each one (on the left of the leaving direction).
struct Spoke {
  int arc;
  double angle;
  int sector_site;
};

std::vector<std::vector<Spoke>> spokes_at_nodes(const Diagram& g) {
  std::vector<std::vector<Spoke>> at(g.nodes.size());
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    const Arc& arc = g.arcs[a];
    if (arc.from == kNone && arc.to == kNone) continue;
    const voronoi::ArcPathView p = voronoi::arc_path(arc, g.nodes);
    if (arc.from != kNone) {
      const Point t = p.tangent(p.s0);
      at[arc.from].push_back({static_cast<int>(a), std::atan2(t.y, t.x), arc.left_site});
    }
    if (arc.to != kNone) {
      const Point t = p.tangent(p.s1);
      at[arc.to].push_back({static_cast<int>(a), std::atan2(-t.y, -t.x), arc.right_site});
    }
  }
  for (auto& s : at) std::sort(s.begin(), s.end(), [](const Spoke& x, const Spoke& y) { return x.angle < y.angle; });
  return at;
}

// The solution circle (or point) of the sensor in sector k at node v, in plane coordinates.
std::optional<SiteConstraint> junction_constraint(const Diagram& g, int v, const std::vector<Spoke>& spokes,
                                                 std::size_t k) {
  const mobius::Complex at(g.nodes[v].x, g.nodes[v].y);
  // The frame's scale: the distance to the nearest other end of the arcs here.
  double L = INFINITY;
  for (const Spoke& s : spokes) {
    const Arc& a = g.arcs[s.arc];
    for (int e : {a.from, a.to})
      if (e != kNone && e != v) L = std::min(L, std::abs(mobius::Complex(g.nodes[e].x, g.nodes[e].y) - at));
  }
  if (!std::isfinite(L) || !(L > 0)) L = 1.0;
  const mobius::NodeFrame frame{at, L};
  mobius::Mobius m;
  const std::size_t n = spokes.size();
  for (std::size_t step = 1; step <= n; ++step) m = mobius::then_invert_in(m, g.arcs[spokes[(k + step) % n].arc], frame);
  if (m.conjugated()) {
    mobius::GeneralizedCircle local = mobius::least_squares_fixed_circle(m);
    if (std::abs(local.A) <= tolerance::kEstimateLineCurvature * std::abs(local.B)) {
      // A solution line through the junction: as a circle of a radius far beyond the map.
      local.A = tolerance::kEstimateLineCurvature * std::abs(local.B);
    }
    const auto c = local.centre();
    const auto r = local.radius();
    if (!c || !r) return std::nullopt;
    return SiteConstraint{true, at + L * *c, L * *r};
  }
  // Even degree: the fixed points of a Möbius map; the junction itself is one of them.
  const auto other = mobius::other_fixed_point(m, tolerance::kEstimateIdentity);
  if (!other) return std::nullopt;
  return SiteConstraint{false, frame.to_plane(*other), 0.0};
}

double cost(const std::vector<SiteConstraint>& cs, mobius::Complex p) {
  double sum = 0;
  for (const auto& c : cs) {
    const double e = c.circle ? std::abs(p - c.centre) - c.radius : std::abs(p - c.centre);
    sum += e * e;
  }
  return sum;
}

mobius::Complex gauss_newton(const std::vector<SiteConstraint>& cs, mobius::Complex p) {
  for (int it = 0; it < 20; ++it) {
    Eigen::Matrix2d jtj = Eigen::Matrix2d::Zero();
    Eigen::Vector2d jtr = Eigen::Vector2d::Zero();
    for (const auto& c : cs) {
      const mobius::Complex d = p - c.centre;
      const double len = std::abs(d);
      if (len == 0) continue;
      const Eigen::Vector2d grad(d.real() / len, d.imag() / len);
      if (c.circle) {
        jtj += grad * grad.transpose();
        jtr += grad * (len - c.radius);
      } else {
        jtj += Eigen::Matrix2d::Identity();
        jtr += Eigen::Vector2d(d.real(), d.imag());
      }
    }
    const Eigen::Vector2d step = jtj.ldlt().solve(jtr);
    if (!step.allFinite()) break;
    p -= mobius::Complex(step(0), step(1));
    if (step.norm() <= tolerance::kEstimateStepStop * (std::abs(p) + 1.0)) break;
  }
  return p;
}

// Points where two constraints meet (or come closest), as starting points.
void starts_from(const SiteConstraint& x, const SiteConstraint& y, std::vector<mobius::Complex>& out) {
  if (!x.circle) return out.push_back(x.centre);
  if (!y.circle) return out.push_back(y.centre);
  const mobius::Complex d = y.centre - x.centre;
  const double dist = std::abs(d);
  if (dist == 0) return;
  const mobius::Complex u = d / dist;
  const double a = (x.radius * x.radius - y.radius * y.radius + dist * dist) / (2 * dist);
  const double h2 = x.radius * x.radius - a * a;
  const double h = std::sqrt(std::max(0.0, h2));
  out.push_back(x.centre + a * u + h * mobius::Complex(0, 1) * u);
  if (h > 0) out.push_back(x.centre + a * u - h * mobius::Complex(0, 1) * u);
}

// 1. Solution circles (or points) of every sensor at every interior junction (a node of degree
// ≥ 3 not on the map's frame), per sensor.
std::vector<std::vector<SiteConstraint>> constraints_at_junctions(const Diagram& g, std::size_t n) {
  std::vector<std::vector<SiteConstraint>> constraints(n);
  const auto spokes = spokes_at_nodes(g);
  for (std::size_t v = 0; v < g.nodes.size(); ++v) {
    const auto& s = spokes[v];
    if (s.size() < 3) continue;
    bool frame = false;
    for (const Spoke& k : s) frame = frame || g.arcs[k.arc].frame;
    if (frame) continue;  // where the map was cut, not where sensors meet
    for (std::size_t k = 0; k < s.size(); ++k) {
      const int site = s[k].sector_site;
      if (site == kNone || static_cast<std::size_t>(site) >= n) continue;
      if (auto c = junction_constraint(g, static_cast<int>(v), s, k)) constraints[site].push_back(*c);
    }
  }
  return constraints;
}

// The starting points of the least-squares intersection: the centroid, the meeting points of every
// pair of the first six constraints and, for a single circle, its point nearest to the centroid.
std::vector<mobius::Complex> start_points(const std::vector<SiteConstraint>& cs, mobius::Complex centroid) {
  std::vector<mobius::Complex> starts{centroid};
  const std::size_t m = std::min<std::size_t>(cs.size(), 6);
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b) starts_from(cs[a], cs[b], starts);
  if (cs.size() == 1 && cs[0].circle) {
    const mobius::Complex d = centroid - cs[0].centre;
    if (std::abs(d) > 0) starts.push_back(cs[0].centre + cs[0].radius * d / std::abs(d));
  }
  return starts;
}

// The least-squares intersection of a sensor's constraints (not empty): Gauss–Newton from every
// start (two or more constraints), the result with the smallest cost winning.
mobius::Complex least_squares_intersection(const std::vector<SiteConstraint>& cs, mobius::Complex centroid) {
  mobius::Complex best = centroid;
  double best_cost = INFINITY;
  for (const mobius::Complex& s0 : start_points(cs, centroid)) {
    const mobius::Complex p = cs.size() >= 2 ? gauss_newton(cs, s0) : s0;
    // Ties in the residual (two intersections of two circles) go to the one nearer the cell.
    const double c = cost(cs, p) + tolerance::kEstimateCentroidPull * std::norm(p - centroid);
    if (std::isfinite(c) && c < best_cost) best_cost = c, best = p;
  }
  return best;
}

// Whether a sensor's junction constraints may leave it a choice: at most two circles and no point.
// Two circles meet at the site and at a second point with the same, zero, residual; a hull sensor's
// two junctions are often the two vertices of one triple of sensors, whose solution circles are
// the same circle (Lemma 5 depends only on the three bisectors), leaving the whole circle.
bool underdetermined(const std::vector<SiteConstraint>& cs) {
  if (cs.empty() || cs.size() > 2) return false;
  return std::all_of(cs.begin(), cs.end(), [](const SiteConstraint& c) { return c.circle; });
}

// 2. Every sensor at its centroid with weight 1; a sensor with junction constraints at their
// least-squares intersection instead (EstimateSource::kJunctions), with its residual.
// Each sensor's solve is its own, so they run on the threads, each writing its own entries.
void locate_at_junctions(const std::vector<std::string>& sensors, std::span<const Point> centroids,
                         const std::vector<std::vector<SiteConstraint>>& constraints, int threads, SiteEstimates& out) {
  parallel_items(sensors.size(), threads, [&](std::size_t i) {
    const mobius::Complex centroid = i < centroids.size() ? mobius::Complex(centroids[i].x, centroids[i].y) : mobius::Complex(0, 0);
    out.sites[i] = {sensors[i], centroid.real(), centroid.imag(), 1.0};
    const auto& cs = constraints[i];
    out.constraints[i] = static_cast<int>(cs.size());
    if (cs.empty()) return;
    const mobius::Complex best = least_squares_intersection(cs, centroid);
    out.sites[i].x = best.real();
    out.sites[i].y = best.imag();
    out.residual[i] = std::sqrt(cost(cs, best) / static_cast<double>(cs.size()));
    out.how[i] = EstimateSource::kJunctions;
  });
}

// An arc between the regions of two different sensors (not the map's frame).
bool separates_two_sensors(const Arc& arc) {
  return !(arc.frame || arc.left_site == kNone || arc.right_site == kNone || arc.left_site == arc.right_site);
}

// Per sensor, its neighbours across the arcs between two sensors: (neighbour, arc).
std::vector<std::vector<std::pair<int, int>>> site_adjacency(const Diagram& g, std::size_t n) {
  std::vector<std::vector<std::pair<int, int>>> neighbours(n);
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    const Arc& arc = g.arcs[a];
    if (!separates_two_sensors(arc)) continue;
    neighbours[arc.left_site].push_back({arc.right_site, static_cast<int>(a)});
    neighbours[arc.right_site].push_back({arc.left_site, static_cast<int>(a)});
  }
  return neighbours;
}

// 3. Sensors whose junctions leave them a choice (underdetermined): Lemma 1 says the site is the
// inversion of a neighbour's site in their common bisector, so across every arc to a neighbour that
// its own junctions determine, the partner of that neighbour's site is one more estimate of the
// site, a point constraint. The least-squares intersection of the junctions' circles and these
// points replaces the centroid's tie-break; exact input gives the site exactly.
void locate_underdetermined(const Diagram& g, const std::vector<std::vector<std::pair<int, int>>>& neighbours,
                            std::span<const Point> centroids, const std::vector<std::vector<SiteConstraint>>& constraints,
                            SiteEstimates& out) {
  const std::size_t n = out.sites.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!underdetermined(constraints[i])) continue;
    std::vector<SiteConstraint> cs = constraints[i];
    for (auto [j, a] : neighbours[i]) {
      if (out.how[j] != EstimateSource::kJunctions || underdetermined(constraints[j])) continue;
      const mobius::WeightedPoint partner =
          mobius::partner_across(plane_curve(g.arcs[a]), {mobius::Complex(out.sites[j].x, out.sites[j].y), 1.0});
      if (std::isfinite(partner.position.real()) && std::isfinite(partner.position.imag()))
        cs.push_back({false, partner.position, 0.0});
    }
    if (cs.size() == constraints[i].size()) continue;
    const mobius::Complex centroid = i < centroids.size() ? mobius::Complex(centroids[i].x, centroids[i].y) : mobius::Complex(0, 0);
    const mobius::Complex best = least_squares_intersection(cs, centroid);
    out.sites[i].x = best.real();
    out.sites[i].y = best.imag();
    out.residual[i] = std::sqrt(cost(constraints[i], best) / static_cast<double>(constraints[i].size()));
  }
}

// 4. Sensors no junction constrains: the inversion of a located neighbour across their common arc
// (EstimateSource::kNeighbour), breadth first from the sensors located at junctions.
void locate_from_neighbours(const Diagram& g, const std::vector<std::vector<std::pair<int, int>>>& neighbours,
                            SiteEstimates& out) {
  const std::size_t n = out.sites.size();
  std::vector<char> located(n, 0);
  std::deque<int> queue;
  for (std::size_t i = 0; i < n; ++i)
    if (out.how[i] == EstimateSource::kJunctions) located[i] = 1, queue.push_back(static_cast<int>(i));
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    for (auto [j, a] : neighbours[i]) {
      if (located[j]) continue;
      const mobius::WeightedPoint partner = mobius::partner_across(plane_curve(g.arcs[a]), {mobius::Complex(out.sites[i].x, out.sites[i].y), 1.0});
      if (!std::isfinite(partner.position.real()) || !std::isfinite(partner.position.imag())) continue;
      out.sites[j].x = partner.position.real();
      out.sites[j].y = partner.position.imag();
      out.how[j] = EstimateSource::kNeighbour;
      located[j] = 1;
      queue.push_back(j);
    }
  }
}

// How much arc a counts in the log-weight system: the number of boundary points of its chain
// (at least 1; 1 without a chain).
double chain_weight(const cleaning::CleanedMap& map, std::size_t a) {
  const std::size_t chain = a < map.arc_chain.size() ? static_cast<std::size_t>(map.arc_chain[a]) : map.chains.size();
  return chain < map.chains.size() ? std::max<double>(1.0, static_cast<double>(map.chains[chain].points.size())) : 1.0;
}

// log(w_left / w_right) of an arc between two sensors: 0 for a line; for a circle, Lemma 1
// (w_in / w_out = |c - s_in| / r = r / |c - s_out|), the geometric mean of its two estimates,
// clamped below 1 (the inside sensor is the lighter one). None when the sites' distances to the
// centre are not usable.
std::optional<double> log_weight_ratio(const Arc& arc, const std::vector<Site>& sites) {
  const auto* c = std::get_if<Circle>(&arc.curve);
  if (!c) return 0.0;
  const int in = arc.ccw ? arc.left_site : arc.right_site;  // the disk is on the left of ccw travel
  const int out_site = in == arc.left_site ? arc.right_site : arc.left_site;
  const mobius::Complex centre(c->cx, c->cy);
  const double din = std::abs(mobius::Complex(sites[in].x, sites[in].y) - centre);
  const double dout = std::abs(mobius::Complex(sites[out_site].x, sites[out_site].y) - centre);
  if (!(din > 0) || !(dout > 0) || !std::isfinite(din / dout)) return std::nullopt;
  const double r = std::min(0.5 * std::log(din / dout), 0.0);
  return in == arc.left_site ? r : -r;
}

// 5. Log weights by least squares over the arcs between sensors (Lemma 1 ratios, weighted by chain
// length), one gauge per component; zero where the system cannot be solved.
Eigen::VectorXd log_weights(const cleaning::CleanedMap& map, const std::vector<Site>& sites) {
  const Diagram& g = map.graph;
  const std::size_t n = sites.size();
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  std::vector<double> diag(n, 0.0);
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    const Arc& arc = g.arcs[a];
    if (!separates_two_sensors(arc)) continue;
    const double w = chain_weight(map, a);
    const std::optional<double> log_ratio = log_weight_ratio(arc, sites);
    if (!log_ratio) continue;
    const int l = arc.left_site, rgt = arc.right_site;
    t.emplace_back(l, rgt, -w);
    t.emplace_back(rgt, l, -w);
    diag[l] += w, diag[rgt] += w;
    rhs(l) += w * *log_ratio;
    rhs(rgt) -= w * *log_ratio;
  }
  // The gauge: a small pull of every log weight to 0 keeps each component's system regular
  // without biasing differences (it shifts a component's mean, which normalisation removes).
  for (std::size_t i = 0; i < n; ++i) t.emplace_back(static_cast<int>(i), static_cast<int>(i), diag[i] + tolerance::kEstimateGaugePull);
  Eigen::SparseMatrix<double> lap(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  lap.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(lap);
  Eigen::VectorXd logw = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  if (solver.info() == Eigen::Success) {
    logw = solver.solve(rhs);
    if (!logw.allFinite()) logw.setZero();
  }
  return logw;
}

}  // namespace

std::string to_string(EstimateSource s) {
  switch (s) {
    case EstimateSource::kJunctions: return "junctions";
    case EstimateSource::kNeighbour: return "neighbour";
    case EstimateSource::kCentroid: return "centroid";
  }
  return "?";
}

SiteEstimates estimate_sites(const cleaning::CleanedMap& map, std::span<const Point> centroids, int threads) {
  const std::size_t n = map.sensors.size();
  SiteEstimates out;
  out.sites.resize(n);
  out.how.assign(n, EstimateSource::kCentroid);
  out.residual.assign(n, 0.0);
  out.constraints.assign(n, 0);

  const std::vector<std::vector<SiteConstraint>> constraints = constraints_at_junctions(map.graph, n);
  locate_at_junctions(map.sensors, centroids, constraints, threads, out);
  const auto neighbours = site_adjacency(map.graph, n);
  locate_underdetermined(map.graph, neighbours, centroids, constraints, out);
  locate_from_neighbours(map.graph, neighbours, out);
  // Weights from their logarithms, the largest 1.
  const Eigen::VectorXd logw = log_weights(map, out.sites);
  const double top = n ? logw.maxCoeff() : 0.0;
  for (std::size_t i = 0; i < n; ++i) out.sites[i].weight = std::exp(logw(static_cast<Eigen::Index>(i)) - top);
  return out;
}

}  // namespace covmap::audit
