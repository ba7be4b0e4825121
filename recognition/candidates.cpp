// The candidate sites of recognize()'s start face: fixed points of its nodes, intersections of
// their solution circles, or points around one circle when all coincide (a family); and the
// failure that names the closest miss when there is no candidate.
#include <algorithm>
#include <complex>
#include <sstream>

#include "recognition/recognize_stages.h"
#include "recognition/tolerances.h"

namespace covmap::recognition::stages {
namespace {

// Tests points against every constraint of the start face and remembers the closest miss.
struct ConstraintTest {
  const TracedGraph& t;
  const std::vector<Constraint>& constraints;
  Violation closest;

  bool satisfies(mobius::Complex p) {
    Violation v{0.0, -1, p};
    for (std::size_t k = 0; k < constraints.size(); ++k) {
      const Constraint& c = constraints[k];
      double off = INFINITY;
      if (c.is_circle) {
        off = mobius::distance_to(c.circle, p);
      } else {
        for (const mobius::Complex& q : c.points) off = std::min(off, std::abs(q - p));
      }
      // A node outside the graph's extent is only as accurate as its distance from it (as a site
      // is, tol_at), and so is what it says about a site near the graph: nearly equal weights put
      // nodes 1e8 out, whose solution circles miss the site by ~1e-3 of an extent of 100.
      const Node& at = t.g.nodes[c.node];
      off = std::max(0.0, off - t.relative * t.extent.distance_to({at.x, at.y}));
      if (off > v.amount) v.amount = off, v.constraint = static_cast<int>(k);
    }
    if (v.amount < closest.amount) closest = v;
    return v.amount <= t.tol_at(p);
  }

  // p as a further candidate when it satisfies every constraint and is no earlier one.
  void add_if_new(std::vector<mobius::Complex>& candidates, mobius::Complex p) {
    if (satisfies(p) && std::none_of(candidates.begin(), candidates.end(),
                                     [&](mobius::Complex q) { return std::abs(q - p) <= t.tol_at(p); }))
      candidates.push_back(p);
  }
};

// Candidates from the solution circles when no node has isolated fixed points: their pairwise
// intersections, or, when all circles coincide, points around the one circle (a family).
void circle_candidates(const std::vector<Constraint>& constraints, double scale, ConstraintTest& test,
                       Candidates& out) {
  std::vector<mobius::GeneralizedCircle> circles;
  for (const Constraint& c : constraints)
    if (c.is_circle) circles.push_back(c.circle);
  bool distinct_pair = false;
  for (std::size_t i = 0; i < circles.size(); ++i)
    for (std::size_t j = i + 1; j < circles.size(); ++j) {
      if (same_circle(circles[i], circles[j], test.t)) continue;
      const auto pts = mobius::intersect(circles[i], circles[j]);
      if (pts.empty()) {
        // Where the two circles come closest (on the line of centres): measured, for the
        // failure's "by how much", never a candidate.
        const auto ci = circles[i].centre(), cj = circles[j].centre();
        const auto ri = circles[i].radius();
        if (ci && cj && ri && std::abs(*cj - *ci) > 0) {
          const mobius::Complex u = (*cj - *ci) / std::abs(*cj - *ci);
          test.satisfies(*ci + *ri * u);
          test.satisfies(*ci - *ri * u);
        }
        continue;
      }
      distinct_pair = true;
      for (const mobius::Complex& p : pts) test.add_if_new(out.points, p);
    }
  if (!distinct_pair && !circles.empty()) {
    // All solution circles coincide (a face with at most two nodes, paper §4.2 k = 2): a
    // one-parameter family. Points around the circle are tried in turn; propagation decides.
    out.family = true;
    const mobius::GeneralizedCircle& c = circles.front();
    out.family_circle = c;
    if (c.is_line()) {
      const mobius::Complex p0 = -c.C * c.B / (2.0 * std::norm(c.B));
      const mobius::Complex dir = mobius::Complex(0, 1) * c.B / std::abs(c.B);
      for (int k = -12; k <= 12; ++k) out.points.push_back(p0 + (0.25 * k * scale) * dir);
    } else if (auto centre = c.centre(); centre && c.radius()) {
      for (int k = 0; k < 24; ++k) out.points.push_back(*centre + std::polar(*c.radius(), (k + 0.5) * 0.2617993877991494));
    }
  }
}

}  // namespace

// Two solution circles that agree within the tolerance are one circle (computed around two
// nodes of the same three bisectors, e.g.): their "intersection" would be rounding noise.
bool same_circle(const mobius::GeneralizedCircle& a, const mobius::GeneralizedCircle& b, const TracedGraph& t) {
  const double tol = t.tol;
  if (a.is_line() != b.is_line()) return false;
  if (a.is_line()) {
    const mobius::Complex ua = a.B / std::abs(a.B), ub = b.B / std::abs(b.B);
    const double sine = std::abs(std::imag(std::conj(ua) * ub));
    const mobius::Complex pa = -a.C * a.B / (2.0 * std::norm(a.B));
    return sine <= std::max(t.relative, tolerance::kSameDirectionSine) && mobius::distance_to(b, pa) <= t.tol_at(pa);
  }
  const auto ca = a.centre(), cb = b.centre();
  const auto ra = a.radius(), rb = b.radius();
  if (!(ca && cb && ra && rb)) return false;
  if (std::max(*ra, *rb) <= t.scale) {
    const double allowed = tol + t.relative * std::max(*ra, *rb);
    return std::abs(*ca - *cb) <= allowed && std::abs(*ra - *rb) <= allowed;
  }
  // A circle larger than the graph (nearly equal weights: radii ~1e12 over an extent of 100) is
  // compared where the graph is, at three points of a spread over the graph's scale: its centre
  // and radius are only good to ulps of the radius, and judging them against `relative` of the
  // radius would take distinct circles for one (a face of 30 nearly equal weights would become a
  // one-parameter family and be rejected).
  const Point middle = t.extent.centre();
  const mobius::Complex p0 = mobius::nearest_point(a, {middle.x, middle.y});
  const mobius::Complex normal = a.A * p0 + a.B;
  if (std::abs(normal) == 0.0) return false;
  const mobius::Complex along = mobius::Complex(0, 1) * normal / std::abs(normal);
  for (const mobius::Complex p : {p0, mobius::nearest_point(a, p0 + t.scale * along),
                                  mobius::nearest_point(a, p0 - t.scale * along)})
    if (mobius::distance_to(b, p) > t.tol_at(p)) return false;
  return true;
}

Candidates start_candidates(const TracedGraph& t, const std::vector<Constraint>& constraints,
                            const std::optional<SiteRegion>& free_root) {
  Candidates out;
  ConstraintTest test{t, constraints, {}};
  out.family = free_root.has_value();
  if (free_root) out.points.push_back({free_root->representative.x, free_root->representative.y});
  for (const Constraint& c : constraints)
    for (const mobius::Complex& p : c.points) test.add_if_new(out.points, p);
  if (out.points.empty() && !free_root) circle_candidates(constraints, t.scale, test, out);
  if (!out.family)
    for (mobius::Complex& p : out.points) p = polish(p, constraints, t.tol_at(p));
  out.closest = test.closest;
  return out;
}

Rejection no_common_point(const TracedGraph& t, int start, const std::vector<Constraint>& constraints,
                          const Violation& closest) {
  const Diagram& g = t.g;
  RecognitionFailure fail;
  fail.face = start;
  std::ostringstream msg;
  msg << "the solution sets of face " << start << " (" << constraints.size()
      << " nodes) have no common point";
  const auto empty_set = std::find_if(constraints.begin(), constraints.end(),
                                      [](const Constraint& c) { return !c.any && !c.is_circle && c.points.empty(); });
  if (empty_set != constraints.end()) {
    fail.node = empty_set->node;
    fail.x = g.nodes[fail.node].x;
    fail.y = g.nodes[fail.node].y;
    fail.amount = empty_set->gap;
    msg << ": going around node " << fail.node << " maps no point to itself (its solution circles miss by "
        << fail.amount << " of the node's scale)";
  } else if (closest.constraint >= 0) {
    fail.node = constraints[closest.constraint].node;
    fail.x = closest.at.real();
    fail.y = closest.at.imag();
    fail.amount = closest.amount;
    msg << ": the best candidate misses the solution set of node " << fail.node << " by " << t.unit * fail.amount;
  }
  fail.message = msg.str();
  return Rejection{fail.message, fail};
}

}  // namespace covmap::recognition::stages
