#include "recognition/tolerances.h"
#include "recognition/recognize.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <deque>
#include <sstream>
#include <thread>

#include "mobius/bisector_relation.h"
#include "core/extent.h"
#include "mobius/feasible_region.h"
#include "mobius/mobius.h"
#include "mobius/node_frame.h"
#include "voronoi/clip.h"
#include "core/parallel.h"
#include "core/large_buffer.h"
#include "voronoi/engine.h"
#include "voronoi/faces.h"

namespace covmap::recognition {
namespace {



mobius::GeneralizedCircle curve_of(const Arc& a) {
  if (const auto* c = std::get_if<Circle>(&a.curve)) return mobius::GeneralizedCircle::from(*c);
  return mobius::GeneralizedCircle::from(std::get<Line>(a.curve));
}

int half_id(const HalfArc& h) { return 2 * h.arc + (h.forward ? 0 : 1); }

// Distance from z to a generalized circle (|value| / |gradient| to first order, exact for circles
// and lines).
double distance_to(const mobius::GeneralizedCircle& g, mobius::Complex z) {
  if (g.is_line()) return std::abs(g.value(z)) / (2.0 * std::abs(g.B));
  const auto c = g.centre();
  const auto r = g.radius();
  if (!c || !r) return INFINITY;
  return std::abs(std::abs(z - *c) - *r);
}

// Intersection points of two generalized circles (0, 1 or 2; empty also when they coincide).
std::vector<mobius::Complex> intersect(mobius::GeneralizedCircle a, mobius::GeneralizedCircle b) {
  auto normalise = [](mobius::GeneralizedCircle g) {
    if (g.A != 0.0) {
      g.B /= g.A;
      g.C /= g.A;
      g.A = 1.0;
    }
    return g;
  };
  a = normalise(a);
  b = normalise(b);
  if (a.is_line() && !b.is_line()) std::swap(a, b);
  // Now a is a circle or both are lines. The radical line of two circles: a - b.
  mobius::GeneralizedCircle line = a;
  if (!a.is_line() && !b.is_line()) {
    line = mobius::GeneralizedCircle{0.0, a.B - b.B, a.C - b.C};
  } else if (b.is_line()) {
    line = b;
  }
  std::vector<mobius::Complex> out;
  if (a.is_line()) {  // two lines: 2Re(conj(B) z) + C = 0 each
    const double a1 = 2 * a.B.real(), b1 = 2 * a.B.imag(), a2 = 2 * b.B.real(), b2 = 2 * b.B.imag();
    const double det = a1 * b2 - a2 * b1;
    if (det == 0.0) return out;
    out.emplace_back((-a.C * b2 + b.C * b1) / det, (-a1 * b.C + a2 * a.C) / det);
    return out;
  }
  if (std::abs(line.B) == 0.0) return out;  // concentric or identical circles
  // Line 2Re(conj(B) z) + C = 0: direction i·B, nearest point to the origin -C B / (2|B|²).
  const mobius::Complex p0 = -line.C * line.B / (2.0 * std::norm(line.B));
  const mobius::Complex dir = mobius::Complex(0, 1) * line.B / std::abs(line.B);
  const mobius::Complex centre = *a.centre();
  const double r = std::sqrt(std::max(0.0, std::norm(centre) - a.C));
  // |p0 + t dir - c|² = r²
  const mobius::Complex w = p0 - centre;
  const double bq = std::real(std::conj(dir) * w);
  const double cq = std::norm(w) - r * r;
  const double disc = bq * bq - cq;
  if (disc < 0) {
    if (disc > -tolerance::kTangentDiscriminant * (r * r + std::norm(w))) out.push_back(p0 - bq * dir);
    return out;
  }
  const double s = std::sqrt(disc);
  out.push_back(p0 + (-bq - s) * dir);
  out.push_back(p0 + (-bq + s) * dir);
  return out;
}

// The clip polygon of a clipped graph: its own if stated, else the frame arcs followed from node to
// node (counter-clockwise, as frame arcs keep the inside on their left).
std::vector<Point> frame_polygon(const Diagram& g) {
  if (!g.clip.empty()) return g.clip;
  std::vector<int> next_arc(g.nodes.size(), kNone);
  int first = kNone;
  for (std::size_t a = 0; a < g.arcs.size(); ++a)
    if (g.arcs[a].frame && g.arcs[a].from != kNone) {
      next_arc[g.arcs[a].from] = static_cast<int>(a);
      if (first == kNone) first = static_cast<int>(a);
    }
  std::vector<Point> poly;
  for (int a = first, guard = 0; a != kNone && guard <= static_cast<int>(g.arcs.size()); ++guard) {
    const auto& n = g.nodes[g.arcs[a].from];
    poly.push_back({n.x, n.y});
    a = next_arc[g.arcs[a].to];
    if (a == first) break;
  }
  return poly;
}

struct FaceSite {
  bool assigned = false;
  mobius::Complex position;
  double weight = 1.0;
};

RecognitionFailure arc_failure(int arc, int face, mobius::Complex where, double amount, std::string message) {
  RecognitionFailure f;
  f.arc = arc;
  f.face = face;
  f.x = where.real();
  f.y = where.imag();
  f.amount = amount;
  f.message = std::move(message);
  return f;
}

// The first arc end (in arc order) farther than `tol` plus rounding from its arc's curve.
struct EndOffCurve {
  int arc = kNone;
  int node = kNone;
  double distance = 0.0;
};
std::optional<EndOffCurve> first_end_off_curve(const Diagram& g, double tol) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  auto scan = [&](std::size_t begin, std::size_t end) -> std::optional<EndOffCurve> {
    for (std::size_t a = begin; a < end; ++a) {
      const Arc& arc = g.arcs[a];
      for (int v : {arc.from, arc.to}) {
        if (v == kNone) continue;
        const double x = g.nodes[v].x, y = g.nodes[v].y;
        double off = 0.0, rounding = 0.0;
        if (const auto* c = std::get_if<Circle>(&arc.curve)) {
          off = std::abs(std::sqrt((x - c->cx) * (x - c->cx) + (y - c->cy) * (y - c->cy)) - c->r);
          rounding = std::abs(c->cx) + std::abs(c->cy) + c->r;
        } else {
          const auto& l = std::get<Line>(arc.curve);
          off = std::abs((x - l.x) * l.dy - (y - l.y) * l.dx) / std::sqrt(l.dx * l.dx + l.dy * l.dy);
          rounding = std::abs(l.x) + std::abs(l.y);
        }
        rounding = tolerance::kArcEndRoundingUlps * eps * (rounding + std::abs(x) + std::abs(y));
        if (!(off <= tol + rounding)) return EndOffCurve{static_cast<int>(a), v, off};
      }
    }
    return std::nullopt;
  };
  const int workers = worker_count(g.arcs.size());
  std::vector<std::optional<EndOffCurve>> found(workers);
  parallel_chunks(g.arcs.size(), workers, [&](std::size_t b, std::size_t e, int w) { found[w] = scan(b, e); });
  for (const auto& f : found)
    if (f) return f;  // chunks are in arc order: the first found is the first arc
  return std::nullopt;
}


// The reconstruction from one site per face: weights equal up to rounding are made equal (see
// RecognitionOptions::weight_snap), faces whose sites coincide within `tol` (orphans) share one
// site, and weights are normalised to a largest of 1. Sites are numbered by their first face.
Reconstruction collect_sites(const LargeVector<FaceSite>& site, double tol, double weight_snap) {
  const int faces = static_cast<int>(site.size());
  // The two orders are independent: one core each.
  LargeVector<double> weight(faces, 0.0);
  auto snap_weights = [&] {
    LargeVector<std::pair<double, int>> order;
    order.reserve(faces);
    for (int f = 0; f < faces; ++f)
      if (site[f].assigned) order.emplace_back(site[f].weight, f);
    std::sort(order.begin(), order.end());  // (weight, face): no ties
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k > 0 && order[k].first - order[k - 1].first <= weight_snap * order[k].first) order[k].first = order[k - 1].first;
      weight[order[k].second] = order[k].first;
    }
  };
  // Coinciding sites through a sweep in x: each face joins the first earlier face (in face order)
  // whose site lies within tol; a union over a window of width tol. The positions travel with the
  // sorted keys, so the sweep reads memory in order.
  struct Keyed {
    double x, y;
    int face;
    bool operator<(const Keyed& o) const { return x < o.x || (x == o.x && face < o.face); }
  };
  LargeVector<Keyed> by_x;
  auto sort_by_x = [&] {
    by_x.reserve(faces);
    for (int f = 0; f < faces; ++f)
      if (site[f].assigned) by_x.push_back({site[f].position.real(), site[f].position.imag(), f});
    std::sort(by_x.begin(), by_x.end());  // (x, face): no ties
  };
  if (worker_count(site.size()) > 1) {
    std::thread other(sort_by_x);
    snap_weights();
    other.join();
  } else {
    snap_weights();
    sort_by_x();
  }
  LargeVector<int> same_as(faces, kNone);  // the earliest face with the same site
  const double tol2 = tol * tol;
  auto close = [&](const Keyed& a, const Keyed& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) <= tol2; };
  for (std::size_t k = 0; k < by_x.size(); ++k) {
    const Keyed& p = by_x[k];
    int earliest = p.face;
    for (std::size_t j = k; j-- > 0;) {
      const Keyed& e = by_x[j];
      if (p.x - e.x > tol) break;
      if (close(e, p)) earliest = std::min(earliest, same_as[e.face] == kNone ? e.face : same_as[e.face]);
    }
    for (std::size_t j = k + 1; j < by_x.size(); ++j) {
      const Keyed& e = by_x[j];
      if (e.x - p.x > tol) break;
      if (e.face < earliest && close(e, p)) earliest = e.face;
    }
    same_as[p.face] = earliest;
  }
  double wmax = 0;
  for (int f = 0; f < faces; ++f) wmax = std::max(wmax, weight[f]);
  Reconstruction r;
  r.sites.reserve(by_x.size());  // at most one site per assigned face
  r.face_site.reserve(faces);
  advise_huge_pages(r.sites.data(), r.sites.capacity() * sizeof(Site));
  advise_huge_pages(r.face_site.data(), r.face_site.capacity() * sizeof(int));
  r.face_site.assign(faces, kNone);
  LargeVector<int> first_face;  // per site, the face it is numbered by
  first_face.reserve(by_x.size());
  for (int f = 0; f < faces; ++f) {
    if (!site[f].assigned) continue;
    const int first = same_as[f];
    if (first != f && r.face_site[first] != kNone) {
      r.face_site[f] = r.face_site[first];
      continue;
    }
    r.face_site[f] = static_cast<int>(first_face.size());
    first_face.push_back(f);
  }
  r.sites.resize(first_face.size());
  parallel_chunks(first_face.size(), worker_count(first_face.size()),
                                   [&](std::size_t b, std::size_t e, int) {
                                     for (std::size_t k = b; k < e; ++k) {
                                       const int f = first_face[k];
                                       r.sites[k] = {"s" + std::to_string(k), site[f].position.real(),
                                                     site[f].position.imag(), weight[f] / wmax};
                                     }
                                   });
  return r;
}

// Paper 5 §3: when no node constrains a site, the sites are fixed by one root site through the
// inversions along a spanning tree of the faces, and each arc asks for its two sites to lie on its
// two sides. Pulled back to the root by the composed (anti-)Möbius map, each such demand is a
// generalized disk for the root's site. The root is an unbounded face when there is one.
SiteRegion root_region(const Diagram& g, const LargeVector<int>& face_of_half,
                       const LargeVector<char>& outside) {
  SiteRegion region;
  const int faces = static_cast<int>(g.faces.size());
  for (int f = 0; f < faces && region.face == kNone; ++f)
    if (!outside[f] && !g.faces[f].bounded) region.face = f;
  for (int f = 0; f < faces && region.face == kNone; ++f)
    if (!outside[f]) region.face = f;
  if (region.face == kNone) return region;
  LargeVector<mobius::Mobius> to_face(faces);
  LargeVector<char> reached(faces, 0), arc_used(g.arcs.size(), 0);
  std::deque<int> queue{region.face};
  reached[region.face] = 1;
  while (!queue.empty()) {
    const int f = queue.front();
    queue.pop_front();
    for (const auto& cycle : g.faces[f].boundaries)
      for (const HalfArc& h : cycle) {
        const Arc& arc = g.arcs[h.arc];
        if (arc.frame || arc_used[h.arc]) continue;
        arc_used[h.arc] = 1;
        const mobius::GeneralizedCircle c = curve_of(arc);
        const bool f_left_is_inside = std::holds_alternative<Line>(arc.curve) ? h.forward : (h.forward == arc.ccw);
        const mobius::GeneralizedCircle side = f_left_is_inside ? c : mobius::GeneralizedCircle{-c.A, -c.B, -c.C};
        region.bounds.push_back(to_face[f].inverse().apply(side));
        const int other = face_of_half[half_id({h.arc, !h.forward})];
        if (other == kNone || reached[other]) continue;
        reached[other] = 1;
        to_face[other] = mobius::Mobius::inversion(c).after(to_face[f]);
        queue.push_back(other);
      }
  }
  return region;
}

}  // namespace

Reconstruction recognize(Diagram input, const RecognitionOptions& options) {
  Reconstruction out;
  using Clock = std::chrono::steady_clock;
  Clock::time_point last = Clock::now();
  auto lap = [&last] {  // seconds since the previous lap
    const Clock::time_point now = Clock::now();
    const double s = std::chrono::duration<double>(now - last).count();
    last = now;
    return s;
  };
  out.graph = std::move(input);
  Diagram& g = out.graph;
  g.sites.clear();
  g.faces.clear();
  // Frame arcs (a clipped map's boundary) are no bisectors: they bound faces but constrain no site.
  bool clipped = false;
  for (const Arc& a : g.arcs)
    if (a.frame) {
      clipped = true;
      break;
    }
  parallel_chunks(g.arcs.size(), worker_count(g.arcs.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t a = b; a < e; ++a) g.arcs[a].left_site = g.arcs[a].right_site = kNone;
  });
  const Box extent = graph_extent(g);
  const double scale = std::max(extent.diagonal(), 1e-300);
  const double tol = options.relative_tolerance * scale;
  // Arcs whose ends are not on their curves: malformed, and invisible to the inversions below,
  // which take each arc through its node (bisector_relation.h).
  if (const auto off = first_end_off_curve(g, tol)) {
    RecognitionFailure fail;
    fail.arc = off->arc;
    fail.node = off->node;
    fail.x = g.nodes[off->node].x;
    fail.y = g.nodes[off->node].y;
    fail.amount = off->distance;
    std::ostringstream msg;
    msg << "arc " << off->arc << ": its end node " << off->node << " is " << off->distance
        << " off the arc's curve (tolerance " << tol << ")";
    fail.message = msg.str();
    out.bisector_graph = false;
    out.reason = fail.message;
    out.failure = fail;
    return out;
  }
  voronoi::FaceIndex face_index;
  voronoi::trace_faces(g, voronoi::FaceLabels::kGeometry, &face_index);
  out.timings.faces = lap();
  const int faces = static_cast<int>(g.faces.size());
  // Per half-arc: its face, and the half-arc after it in the face's boundary cycle.
  const LargeVector<int>& face_of_half = face_index.face_of_half;
  const LargeVector<int>& next_half = face_index.next_half;

  // Nodes on the frame are where the map was cut, not where sites meet: they give no solution
  // circle.
  LargeVector<char> on_frame(g.nodes.size(), 0);
  for (const Arc& a : g.arcs)
    if (a.frame)
      for (int v : {a.from, a.to})
        if (v != kNone) on_frame[v] = 1;
  // The face outside the frame (on the right of frame arcs) has no site.
  LargeVector<char> outside(faces, 0);
  for (std::size_t a = 0; a < g.arcs.size(); ++a)
    if (g.arcs[a].frame && face_of_half[2 * a + 1] != kNone) outside[face_of_half[2 * a + 1]] = 1;


  // Lemmas 5 and §4.4: going once around node v from face f, across every arc at v and back, maps
  // f's site to itself. The composition of the inversions is an anti-Möbius map for an odd number
  // of arcs (its fixed set: a circle — the solution circle — or at most two points) and a Möbius
  // map for an even number (at most two fixed points, or no constraint when it is the identity).
  struct Constraint {
    int node = kNone;            // the node it comes from
    bool any = false;            // no constraint
    bool is_circle = false;
    mobius::GeneralizedCircle circle;
    std::vector<mobius::Complex> points;
    // Odd degree, fixed set empty: the two circles whose intersection it is miss each other by
    // this much (how far the node is from being a node of a bisector graph).
    double gap = 0.0;
  };
  // Composed in the node's own frame z' = (z - v) / L, where every arc at v passes through the
  // origin and has a normalised form: an arc of a huge circle (nearly equal weights) is then a
  // near-reflection with O(1) matrix entries, where in plane coordinates its inversion matrix has
  // entries ~R² that cancel in the composition (the solution circle would lose ~(R/L)² digits).
  auto node_constraint = [&](int f, int h_out) -> std::optional<Constraint> {
    const Arc& first = g.arcs[h_out / 2];
    const int v = (h_out % 2 == 0) ? first.from : first.to;
    const mobius::Complex at(g.nodes[v].x, g.nodes[v].y);
    const int far_end = (h_out % 2 == 0) ? first.to : first.from;
    double L = far_end != kNone ? std::abs(mobius::Complex(g.nodes[far_end].x, g.nodes[far_end].y) - at) : 0.0;
    if (!(L > 0)) L = scale;
    mobius::Mobius h_total;
    int h = h_out, face = f, steps = 0;
    do {
      if (h == kNone || g.arcs[h / 2].frame) return std::nullopt;
      h_total = mobius::Mobius::inversion(mobius::curve_through_origin(g.arcs[h / 2], at, L)).after(h_total);
      const int twin = h ^ 1;
      face = face_of_half[twin];
      h = next_half[twin];
      if (++steps > 64) return std::nullopt;
    } while (face != f || h != h_out);
    const double norm = std::max({std::abs(h_total.a()), std::abs(h_total.b()),
                                  std::abs(h_total.c()), std::abs(h_total.d())});
    const double mt = options.matrix_tolerance * norm;
    Constraint c;
    if (h_total.conjugated()) {
      const auto forms = h_total.fixed_set_forms();
      auto size = [](const mobius::GeneralizedCircle& x) { return std::abs(x.A) + std::abs(x.B) + std::abs(x.C); };
      const double n0 = size(forms[0]), n1 = size(forms[1]);
      const mobius::GeneralizedCircle& big = n0 >= n1 ? forms[0] : forms[1];
      const mobius::GeneralizedCircle& small = n0 >= n1 ? forms[1] : forms[0];
      const double ratio = std::min(n0, n1) / std::max(n0, n1);
      // Proportional forms (or a vanishing one) describe one circle.
      const double lambda = (small.A * big.A + std::real(std::conj(small.B) * big.B) + small.C * big.C) /
                            (big.A * big.A + std::norm(big.B) + big.C * big.C);
      const double residual = std::abs(small.A - lambda * big.A) + std::abs(small.B - lambda * big.B) +
                              std::abs(small.C - lambda * big.C);
      if (ratio < options.matrix_tolerance || residual <= options.matrix_tolerance * std::max(n0, n1)) {
        c.is_circle = true;
        c.circle = big;
      } else {
        c.points = intersect(forms[0], forms[1]);
        if (c.points.empty()) {
          const auto c0 = forms[0].centre(), c1 = forms[1].centre();
          const auto r0 = forms[0].radius(), r1 = forms[1].radius();
          if (c0 && c1 && r0 && r1) {
            const double between = std::abs(*c0 - *c1);
            c.gap = std::max(between - *r0 - *r1, std::abs(*r0 - *r1) - between);
          } else {
            c.gap = INFINITY;  // an imaginary circle or parallel lines: no point at all
          }
        }
      }
    } else {
      const mobius::Complex a = h_total.a(), b = h_total.b(), cc = h_total.c(), d = h_total.d();
      if (std::abs(b) <= mt && std::abs(cc) <= mt && std::abs(a - d) <= mt) {
        c.any = true;  // the identity: this node constrains nothing
      } else if (std::abs(cc) <= mt) {
        if (std::abs(d - a) > mt) c.points.push_back(b / (d - a));
      } else {
        // c z² + (d - a) z - b = 0
        const mobius::Complex disc = std::sqrt((d - a) * (d - a) + 4.0 * cc * b);
        c.points.push_back((-(d - a) + disc) / (2.0 * cc));
        c.points.push_back((-(d - a) - disc) / (2.0 * cc));
      }
    }
    // Back to the plane.
    const mobius::Mobius to_plane(mobius::Complex(L, 0.0), at, mobius::Complex(0.0, 0.0), mobius::Complex(1.0, 0.0), false);
    // A solution circle through the node whose radius exceeds L / matrix_tolerance is its tangent
    // line to within the tolerance over the node's neighbourhood: a line (A exactly 0), so that a
    // rounding-level A does not become a circle of radius 1e16 in plane coordinates.
    if (c.is_circle && std::abs(c.circle.A) <= options.matrix_tolerance * std::abs(c.circle.B)) c.circle.A = 0.0;
    if (c.is_circle) c.circle = to_plane.apply(c.circle);
    for (mobius::Complex& p : c.points) p = at + L * p;
    return c;
  };

  // The face whose nodes give the most constraints; each node counted once per face.
  int start = -1;
  std::vector<Constraint> constraints;
  for (int f = 0; f < faces; ++f) {
    if (outside[f]) continue;
    std::vector<Constraint> found;
    std::vector<int> seen_nodes;
    for (const auto& cycle : g.faces[f].boundaries)
      for (const HalfArc& hh : cycle) {
        const Arc& arc = g.arcs[hh.arc];
        const int v = hh.forward ? arc.from : arc.to;  // hh starts at v
        if (v == kNone || on_frame[v] || arc.frame) continue;
        if (std::find(seen_nodes.begin(), seen_nodes.end(), v) != seen_nodes.end()) continue;
        seen_nodes.push_back(v);
        if (auto c = node_constraint(f, half_id(hh)); c && !c->any) {
          c->node = v;
          found.push_back(*c);
        }
      }
    if (found.size() > constraints.size()) start = f, constraints = std::move(found);
    if (constraints.size() >= 6) break;  // plenty: a bounded amount of work for the start face
  }
  std::optional<SiteRegion> free_root;
  if (start < 0 || constraints.empty()) {
    // No node fixes any site (paper 5, §3): the root's site ranges over a region.
    SiteRegion region = root_region(g, face_of_half, outside);
    if (region.face == kNone) {
      out.bisector_graph = false;
      out.reason = "the graph has no face that could hold a site";
      return out;
    }
    const mobius::FeasibleRegion fr = mobius::feasible_region(region.bounds, mobius::Complex(0.5 * (extent.xmin + extent.xmax), 0.5 * (extent.ymin + extent.ymax)),
                                              std::max(2.0 * scale, 1.0));
    if (fr.empty) {
      RecognitionFailure fail;
      fail.face = region.face;
      std::ostringstream msg;
      msg << "no position for the site of face " << region.face << " puts every pair of sites on the two sides of their arc ("
          << region.bounds.size() << " conditions, paper 5 §3: the solution set is empty)";
      fail.message = msg.str();
      out.bisector_graph = false;
      out.reason = fail.message;
      out.failure = fail;
      return out;
    }
    region.representative = {fr.representative.real(), fr.representative.imag()};
    region.margin = fr.margin;
    start = region.face;
    free_root = std::move(region);
  }
  // How far p is from satisfying every constraint of the start face, and which constraint is
  // farthest; the point that came closest is named when none satisfies all.
  struct Violation {
    double amount = INFINITY;
    int constraint = -1;
    mobius::Complex at;
  };
  Violation closest;
  auto satisfies = [&](mobius::Complex p) {
    Violation v{0.0, -1, p};
    for (std::size_t k = 0; k < constraints.size(); ++k) {
      const Constraint& c = constraints[k];
      double off = INFINITY;
      if (c.is_circle) {
        off = distance_to(c.circle, p);
      } else {
        for (const mobius::Complex& q : c.points) off = std::min(off, std::abs(q - p));
      }
      if (off > v.amount) v.amount = off, v.constraint = static_cast<int>(k);
    }
    if (v.amount < closest.amount) closest = v;
    return v.amount <= tol;
  };
  std::vector<mobius::Complex> candidates;
  bool family = free_root.has_value();
  if (free_root) candidates.push_back({free_root->representative.x, free_root->representative.y});
  for (const Constraint& c : constraints)
    for (const mobius::Complex& p : c.points)
      if (satisfies(p) && std::none_of(candidates.begin(), candidates.end(),
                                       [&](mobius::Complex q) { return std::abs(q - p) <= tol; }))
        candidates.push_back(p);
  if (candidates.empty() && !free_root) {
    std::vector<mobius::GeneralizedCircle> circles;
    for (const Constraint& c : constraints)
      if (c.is_circle) circles.push_back(c.circle);
    bool distinct_pair = false;
    // Two solution circles that agree within the tolerance are one circle (computed around two
    // nodes of the same three bisectors, e.g.): their "intersection" would be rounding noise.
    auto same_circle = [&](const mobius::GeneralizedCircle& a, const mobius::GeneralizedCircle& b) {
      if (a.is_line() != b.is_line()) return false;
      if (a.is_line()) {
        const mobius::Complex ua = a.B / std::abs(a.B), ub = b.B / std::abs(b.B);
        const double sine = std::abs(std::imag(std::conj(ua) * ub));
        const mobius::Complex pa = -a.C * a.B / (2.0 * std::norm(a.B));
        return sine <= options.matrix_tolerance && distance_to(b, pa) <= tol;
      }
      const auto ca = a.centre(), cb = b.centre();
      const auto ra = a.radius(), rb = b.radius();
      return ca && cb && ra && rb && std::abs(*ca - *cb) <= tol && std::abs(*ra - *rb) <= tol;
    };
    for (std::size_t i = 0; i < circles.size(); ++i)
      for (std::size_t j = i + 1; j < circles.size(); ++j) {
        if (same_circle(circles[i], circles[j])) continue;
        const auto pts = intersect(circles[i], circles[j]);
        if (pts.empty()) {
          // Where the two circles come closest (on the line of centres): measured, for the
          // failure's "by how much", never a candidate.
          const auto ci = circles[i].centre(), cj = circles[j].centre();
          const auto ri = circles[i].radius();
          if (ci && cj && ri && std::abs(*cj - *ci) > 0) {
            const mobius::Complex u = (*cj - *ci) / std::abs(*cj - *ci);
            satisfies(*ci + *ri * u);
            satisfies(*ci - *ri * u);
          }
          continue;
        }
        distinct_pair = true;
        for (const mobius::Complex& p : pts)
          if (satisfies(p) && std::none_of(candidates.begin(), candidates.end(),
                                           [&](mobius::Complex q) { return std::abs(q - p) <= tol; }))
            candidates.push_back(p);
      }
    if (!distinct_pair && !circles.empty()) {
      // All solution circles coincide (a face with at most two nodes, paper §4.2 k = 2): a
      // one-parameter family. Points around the circle are tried in turn; propagation decides.
      family = true;
      const mobius::GeneralizedCircle& c = circles.front();
      if (c.is_line()) {
        const mobius::Complex p0 = -c.C * c.B / (2.0 * std::norm(c.B));
        const mobius::Complex dir = mobius::Complex(0, 1) * c.B / std::abs(c.B);
        for (int k = -12; k <= 12; ++k) candidates.push_back(p0 + (0.25 * k * scale) * dir);
      } else if (auto centre = c.centre(); centre && c.radius()) {
        for (int k = 0; k < 24; ++k) candidates.push_back(*centre + std::polar(*c.radius(), (k + 0.5) * 0.2617993877991494));
      }
    }
  }
  // Gauss-Newton on the distances to the solution circles among `cs`: an intersection of two
  // circles alone can be ill-conditioned when they meet at a shallow angle.
  auto polish = [&](mobius::Complex p, const std::vector<Constraint>& cs) {
    for (int it = 0; it < 4; ++it) {
      double jtj[3] = {0, 0, 0}, jtr[2] = {0, 0};
      int used = 0;
      for (const Constraint& c : cs) {
        if (!c.is_circle || c.circle.is_line()) continue;
        const auto centre = c.circle.centre();
        const auto radius = c.circle.radius();
        if (!centre || !radius) continue;
        const mobius::Complex d = p - *centre;
        const double len = std::abs(d);
        if (len == 0) continue;
        const double res = len - *radius;
        const double gx = d.real() / len, gy = d.imag() / len;
        jtj[0] += gx * gx, jtj[1] += gx * gy, jtj[2] += gy * gy;
        jtr[0] += gx * res, jtr[1] += gy * res;
        ++used;
      }
      if (used < 2) break;
      const double det = jtj[0] * jtj[2] - jtj[1] * jtj[1];
      if (!(std::abs(det) > tolerance::kSingularNormalEquations * (jtj[0] + jtj[2]) * (jtj[0] + jtj[2])))
        break;  // near-parallel circles
      const double dx = (jtj[2] * jtr[0] - jtj[1] * jtr[1]) / det;
      const double dy = (jtj[0] * jtr[1] - jtj[1] * jtr[0]) / det;
      if (!std::isfinite(dx) || !std::isfinite(dy) || std::hypot(dx, dy) > tol) break;
      p -= mobius::Complex(dx, dy);
    }
    return p;
  };
  if (!family)
    for (mobius::Complex& p : candidates) p = polish(p, constraints);
  // The solution circles of the nodes of face f (at most four), for re-anchoring the sites of faces
  // at degenerate nodes (FaceIndex::degenerate_node: rounding of the sites decides their
  // combinatorics, and re-anchoring on the nodes' solution circles lets the recomputed diagram
  // reproduce them).
  auto face_constraints = [&](int f) {
    std::vector<Constraint> cs;
    std::vector<int> seen_nodes;
    for (const auto& cycle : g.faces[f].boundaries)
      for (const HalfArc& hh : cycle) {
        const Arc& arc = g.arcs[hh.arc];
        const int v = hh.forward ? arc.from : arc.to;
        if (v == kNone || on_frame[v] || arc.frame) continue;
        if (std::find(seen_nodes.begin(), seen_nodes.end(), v) != seen_nodes.end()) continue;
        seen_nodes.push_back(v);
        if (auto c = node_constraint(f, half_id(hh)); c && c->is_circle) cs.push_back(*c);
        if (cs.size() >= 4) return cs;
      }
    return cs;
  };
  // Faces at a degenerate node: those on either side of an arc ending there.
  LargeVector<char> at_degenerate_node(faces, 0);
  {
    const LargeVector<char>& degenerate = face_index.degenerate_node;
    for (std::size_t a = 0; a < g.arcs.size(); ++a) {
      const Arc& arc = g.arcs[a];
      if (!((arc.from != kNone && degenerate[arc.from]) || (arc.to != kNone && degenerate[arc.to]))) continue;
      for (int h : {static_cast<int>(2 * a), static_cast<int>(2 * a + 1)})
        if (face_of_half[h] != kNone) at_degenerate_node[face_of_half[h]] = 1;
    }
  }
  if (candidates.empty()) {
    out.bisector_graph = false;
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
          << fail.amount << ")";
    } else if (closest.constraint >= 0) {
      fail.node = constraints[closest.constraint].node;
      fail.x = closest.at.real();
      fail.y = closest.at.imag();
      fail.amount = closest.amount;
      msg << ": the best candidate misses the solution set of node " << fail.node << " by " << fail.amount;
    }
    fail.message = msg.str();
    out.reason = fail.message;
    out.failure = fail;
    return out;
  }
  out.timings.start = lap();
  const double tol2 = tol * tol;
  // Each candidate is propagated breadth first along a spanning tree of the faces (Lemma 1 across
  // each tree arc, bisector_relation.h: exact to a few ulps however large the circle, so no
  // re-anchoring except at degenerate nodes); then every arc is verified, independently and on
  // both cores: each of its sites on its own side, and the two sites mirror images in it.
  std::vector<Reconstruction> solutions;
  std::optional<RecognitionFailure> last_failure;
  LargeVector<FaceSite> site(faces);
  LargeVector<char> reached(faces);
  LargeVector<int> queue;
  queue.reserve(faces);
  // The first failure of arcs [b, e) (in arc order), if any.
  auto verify_arcs = [&](std::size_t b, std::size_t e) -> std::optional<RecognitionFailure> {
    for (std::size_t a = b; a < e; ++a) {
      const Arc& arc = g.arcs[a];
      const int left = face_of_half[2 * a], right = face_of_half[2 * a + 1];
      if (arc.frame || left == kNone || right == kNone || !site[left].assigned || !site[right].assigned) continue;
      const mobius::ArcBisector bis = mobius::arc_bisector(arc, g.nodes);
      // The face on the left must hold its site on that side: inside the disk when the arc runs
      // counter-clockwise, on the left of a line; the face on the right the other side.
      const bool left_is_inside = bis.line || arc.ccw;
      for (const int f : {left, right}) {
        const mobius::Complex p = site[f].position;
        if (mobius::strictly_inside(bis, p) == (left_is_inside == (f == left))) continue;
        const double off = distance_to(curve_of(arc), p);
        if (off > tol) {
          std::ostringstream msg;
          msg << "arc " << a << ": the site of face " << f << " lies on the wrong side of it";
          return arc_failure(static_cast<int>(a), f, p, off, msg.str());
        }
      }
      const mobius::WeightedPoint partner = mobius::partner_across(bis, {site[left].position, site[left].weight});
      const double off2 = std::norm(site[right].position - partner.position);
      if (!(off2 <= tol2)) {
        const double off = std::sqrt(off2);
        std::ostringstream msg;
        msg << "arc " << a << ": the sites of faces " << left << " and " << right
            << " are not mirror images in it (off by " << off << ")";
        return arc_failure(static_cast<int>(a), right, partner.position, off, msg.str());
      }
    }
    return std::nullopt;
  };
  for (const mobius::Complex& p : candidates) {
    std::fill(site.begin(), site.end(), FaceSite{});
    // A byte per face (1 MB at 10^6 faces, cache-resident) for the test every half-arc makes.
    std::fill(reached.begin(), reached.end(), 0);
    site[start] = {true, p, 1.0};
    reached[start] = 1;
    queue.assign(1, start);
    // Memory latency bound (faces, their boundaries and the faces across are scattered at 10^6
    // faces): the data of the faces a few places ahead in the queue is prefetched in stages.
    auto prefetch_face = [&](std::size_t at) {
      if (at < queue.size()) __builtin_prefetch(&g.faces[queue[at]]);
    };
    auto prefetch_boundary = [&](std::size_t at) {
      if (at >= queue.size()) return;
      const auto& b = g.faces[queue[at]].boundaries;
      if (!b.empty()) __builtin_prefetch(b.front().data());
    };
    auto prefetch_across = [&](std::size_t at) {
      if (at >= queue.size()) return;
      const auto& b = g.faces[queue[at]].boundaries;
      if (b.empty()) return;
      for (const HalfArc& h : b.front()) __builtin_prefetch(&face_of_half[half_id({h.arc, !h.forward})]);
    };
    for (std::size_t head = 0; head < queue.size(); ++head) {
      prefetch_face(head + 12);
      prefetch_boundary(head + 8);
      prefetch_across(head + 4);
      const int f = queue[head];
      const FaceSite here = site[f];
      for (const auto& cycle : g.faces[f].boundaries)
        for (const HalfArc& h : cycle) {
          const int other = face_of_half[half_id({h.arc, !h.forward})];
          if (other == kNone || reached[other] || g.arcs[h.arc].frame) continue;
          reached[other] = 1;
          const mobius::WeightedPoint partner = mobius::partner_across(mobius::arc_bisector(g.arcs[h.arc], g.nodes), {here.position, here.weight});
          const mobius::Complex at = at_degenerate_node[other] ? polish(partner.position, face_constraints(other)) : partner.position;
          site[other] = {true, at, partner.weight};
          queue.push_back(other);
        }
    }
    const int workers = worker_count(g.arcs.size());
    std::vector<std::optional<RecognitionFailure>> found(workers);
    parallel_chunks(g.arcs.size(), workers,
                                     [&](std::size_t b, std::size_t e, int w) { found[w] = verify_arcs(b, e); });
    std::optional<RecognitionFailure> failure;
    for (auto& f : found)
      if (f && !failure) failure = std::move(f);
    if (failure) {
      last_failure = failure;
      out.timings.propagate += lap();
      continue;
    }
    out.timings.propagate += lap();
    solutions.push_back(collect_sites(site, tol, options.weight_snap));
    out.timings.sites += lap();
  }
  if (solutions.empty()) {
    out.bisector_graph = false;
    out.failure = last_failure;
    out.reason = last_failure ? last_failure->message : "no candidate survived";
    return out;
  }
  out.bisector_graph = true;
  out.unique = !family;
  if (solutions.size() > 1 && !family)
    for (const auto& s : solutions) out.candidates.push_back(s.sites);
  out.sites = std::move(solutions.front().sites);
  out.face_site = std::move(solutions.front().face_site);
  out.region = free_root;
  out.reason = free_root ? "every arc separates mirror-image sites; no node fixes the sites: the site of face " +
                               std::to_string(free_root->face) + " may lie anywhere in a region (see region), this is one choice"
               : family  ? "every arc separates mirror-image sites; the sites are not unique (a "
                           "one-parameter family along a solution circle): this is one of them"
                         : "every arc separates mirror-image sites";
  if (options.voronoi_check) {
    // The sites must be distinct for a Voronoi diagram; coinciding sites already answer "no".
    try {
      Diagram recomputed = voronoi::build_diagram(out.sites);
      if (clipped) recomputed = voronoi::clip_diagram(recomputed, frame_polygon(g));
      CompareOptions co;
      co.relative_tolerance = options.relative_tolerance;
      const Comparison c = compare_graphs(g, recomputed, co);
      out.voronoi = c.equal() ? MwvdAnswer::kYes : MwvdAnswer::kNo;
      out.voronoi_differences = c.differences;
    } catch (const voronoi::InvalidSites& e) {
      out.voronoi = MwvdAnswer::kNo;
      out.voronoi_differences.push_back({DifferenceKind::NodeOnlyInA, kNone, 0, 0, e.what()});
    }
    out.timings.voronoi_check = lap();
  }
  return out;
}

}  // namespace covmap::recognition
