// Pass 1: indices, finiteness, arc ends on their curves, line direction, faces. Decides which
// sites, nodes and arcs the geometric passes may use; it also collects each node's sites.
#include <algorithm>
#include <cmath>
#include <variant>

#include "check/check_internal.h"

namespace covmap::check::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr Point kNowhere{kNaN, kNaN};

bool finite(double a, double b, double c = 0.0, double e = 0.0) {
  return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(e);
}

void check_sites_and_nodes(CheckContext& c) {
  const Diagram& d = c.d;
  c.site_ok.assign(d.sites.size(), 0);
  for (std::size_t i = 0; i < d.sites.size(); ++i) {
    const Site& s = d.sites[i];
    c.site_ok[i] = site_is_valid(s);
    if (!c.site_ok[i]) {
      Violation ids;
      ids.site = static_cast<int>(i);
      c.add(ViolationKind::BadSite, kNowhere,
            strf("site %zu ('%s') has position (%g, %g) and weight %g; need finite values and a "
                 "positive weight",
                 i, s.id.c_str(), s.x, s.y, s.weight),
            ids);
    }
  }
  c.node_ok.assign(d.nodes.size(), 0);
  for (std::size_t n = 0; n < d.nodes.size(); ++n) {
    c.node_ok[n] = finite(d.nodes[n].x, d.nodes[n].y);
    if (!c.node_ok[n]) {
      Violation ids;
      ids.node = static_cast<int>(n);
      c.add(ViolationKind::BadNode, kNowhere, strf("node %zu is not finite", n), ids);
    }
  }
}

// Index checks of one arc; false when the arc cannot be used further. Reports what is wrong.
bool arc_indices_ok(CheckContext& c, int a) {
  const Diagram& d = c.d;
  const Arc& arc = d.arcs[a];
  Violation ids;
  ids.arc = a;
  bool ok = true;
  const auto bad = [&](ViolationKind kind, const std::string& text) {
    c.add(kind, kNowhere, strf("arc %d: %s", a, text.c_str()), ids);
    ok = false;
  };
  const int n_nodes = static_cast<int>(d.nodes.size());
  const int n_sites = static_cast<int>(d.sites.size());
  for (const int v : {arc.from, arc.to}) {
    if (v != kNone && (v < 0 || v >= n_nodes))
      bad(ViolationKind::BadIndex, strf("node index %d out of range [0, %d)", v, n_nodes));
    else if (v != kNone && !c.node_ok[v])
      ok = false;  // already reported as BadNode
  }
  for (const int s : {arc.left_site, arc.right_site}) {
    if (s != kNone && (s < 0 || s >= n_sites))
      bad(ViolationKind::BadIndex, strf("site index %d out of range [0, %d)", s, n_sites));
    else if (s != kNone && !c.site_ok[s])
      ok = false;  // already reported as BadSite
  }
  const int sides_set = (arc.left_site != kNone) + (arc.right_site != kNone);
  if (arc.frame && sides_set != 1)
    bad(ViolationKind::BadIndex, "a frame arc needs exactly one site side (the other is kNone)");
  if (!arc.frame && sides_set != 2) bad(ViolationKind::BadIndex, "a bisector arc needs two sites");
  if (!arc.frame && sides_set == 2 && arc.left_site == arc.right_site)
    bad(ViolationKind::BadIndex, strf("left and right site are both %d", arc.left_site));
  if (const auto* circle = std::get_if<Circle>(&arc.curve)) {
    if (!finite(circle->cx, circle->cy, circle->r) || !(circle->r > 0.0))
      bad(ViolationKind::BadCurve,
          strf("circle (%g, %g) r=%g is not finite with r > 0", circle->cx, circle->cy, circle->r));
    if ((arc.from == kNone) != (arc.to == kNone))
      bad(ViolationKind::BadIndex, "a circle arc needs both end nodes or neither (full circle)");
  } else {
    const Line& l = std::get<Line>(arc.curve);
    if (!finite(l.x, l.y, l.dx, l.dy) || (l.dx == 0.0 && l.dy == 0.0))
      bad(ViolationKind::BadCurve, "line is not finite or has a zero direction");
  }
  return ok;
}

void check_arcs_structure(CheckContext& c) {
  const Diagram& d = c.d;
  c.paths.assign(d.arcs.size(), std::nullopt);
  c.node_sites.assign(d.nodes.size(), {});
  for (int a = 0; a < static_cast<int>(d.arcs.size()); ++a) {
    const Arc& arc = d.arcs[a];
    if (!arc_indices_ok(c, a)) continue;
    for (const int n : {arc.from, arc.to}) {
      if (n == kNone) continue;
      for (const int s : {arc.left_site, arc.right_site}) {
        std::vector<int>& sites = c.node_sites[n];
        if (s != kNone && std::find(sites.begin(), sites.end(), s) == sites.end())
          sites.push_back(s);
      }
    }
    ArcPath path = make_arc_path(arc, d.nodes);
    Violation ids;
    ids.arc = a;
    const int distinct_ends[2] = {arc.from, arc.to == arc.from ? kNone : arc.to};
    for (const int n : distinct_ends) {
      if (n == kNone) continue;
      const Point p{d.nodes[n].x, d.nodes[n].y};
      const double off = distance_to_curve(path, p);
      path.end_gap = std::max(path.end_gap, off);
      const double tol =
          c.tol(std::max(CheckContext::magnitude(p), representation_magnitude(path)));
      if (off > tol) {
        ids.node = n;
        c.add(ViolationKind::ArcEndNotOnCurve, p,
              strf("arc %d: end node %d is %.3g from the arc's curve (tolerance %.3g)", a, n, off,
                   tol),
              ids);
      }
    }
    if (!path.circle && path.bounded() && path.s1 < path.s0) {
      if (path.s0 - path.s1 > c.tol(CheckContext::magnitude(path.from_point) +
                                    CheckContext::magnitude(path.to_point))) {
        ids.node = kNone;
        c.add(ViolationKind::LineArcReversed, path.from_point,
              strf("arc %d: line arc runs from node %d to node %d against its direction +d", a,
                   arc.from, arc.to),
              ids);
        continue;
      }
      path.s1 = path.s0;  // the ends coincide within eps: a degenerate, zero-length arc
    }
    c.paths[a] = path;
  }
}

// Where a half-arc starts and ends (kNone at infinity or for a full circle).
int start_of(const Arc& arc, bool forward) { return forward ? arc.from : arc.to; }
int end_of(const Arc& arc, bool forward) { return forward ? arc.to : arc.from; }

void check_faces(CheckContext& c) {
  const Diagram& d = c.d;
  const int n_arcs = static_cast<int>(d.arcs.size());
  for (int f = 0; f < static_cast<int>(d.faces.size()); ++f) {
    const Face& face = d.faces[f];
    Violation ids;
    ids.face = f;
    if (face.site < 0 || face.site >= static_cast<int>(d.sites.size())) {
      c.add(ViolationKind::BadIndex, kNowhere,
            strf("face %d: site index %d out of range", f, face.site), ids);
      continue;
    }
    if (face.cycles_begin < 0 || face.cycles_end < face.cycles_begin ||
        face.cycles_end > static_cast<int>(d.cycles.size())) {
      c.add(ViolationKind::BadIndex, kNowhere,
            strf("face %d: cycle range [%d, %d) out of range (%zu cycles)", f, face.cycles_begin, face.cycles_end,
                 d.cycles.size()),
            ids);
      continue;
    }
    const FaceCycles cycles = face_cycles(d, face);
    for (std::size_t b = 0; b < cycles.size(); ++b) {
      const CycleRange& range = d.cycles[face.cycles_begin + b];
      if (range.begin < 0 || range.end < range.begin || range.end > static_cast<int>(d.half_arcs.size())) {
        c.add(ViolationKind::BadIndex, kNowhere,
              strf("face %d boundary %zu: half-arc range [%d, %d) out of range (%zu half-arcs)", f, b, range.begin,
                   range.end, d.half_arcs.size()),
              ids);
        continue;
      }
      const auto cycle = cycles[b];
      bool indices_ok = true;
      for (const HalfArc& h : cycle) {
        if (h.arc < 0 || h.arc >= n_arcs) {
          ids.arc = h.arc;
          c.add(ViolationKind::BadIndex, kNowhere,
                strf("face %d boundary %zu: arc index %d out of range", f, b, h.arc), ids);
          indices_ok = false;
        }
      }
      if (!indices_ok) continue;
      for (std::size_t k = 0; k < cycle.size(); ++k) {
        const Arc& arc = d.arcs[cycle[k].arc];
        const int side = cycle[k].forward ? arc.left_site : arc.right_site;
        ids.arc = cycle[k].arc;
        if (side != face.site) {
          c.add(ViolationKind::FaceInconsistent, kNowhere,
                strf("face %d (site %d) is on the side of arc %d that names site %d", f, face.site,
                     cycle[k].arc, side),
                ids);
        }
        const HalfArc& next = cycle[(k + 1) % cycle.size()];
        const int end = end_of(arc, cycle[k].forward);
        const int next_start = start_of(d.arcs[next.arc], next.forward);
        if (end != next_start) {
          c.add(ViolationKind::FaceInconsistent, kNowhere,
                strf("face %d boundary %zu: arc %d ends at node %d but the next arc %d starts at "
                     "node %d",
                     f, b, cycle[k].arc, end, next.arc, next_start),
                ids);
        }
      }
    }
  }
}

}  // namespace

void check_structure(CheckContext& c) {
  check_sites_and_nodes(c);
  check_arcs_structure(c);
  check_faces(c);
  // The region where unbounded arcs are sampled: everything the diagram names, with a margin.
  Box box;
  for (std::size_t i = 0; i < c.d.sites.size(); ++i)
    if (c.site_ok[i]) box.add({c.d.sites[i].x, c.d.sites[i].y});
  for (std::size_t n = 0; n < c.d.nodes.size(); ++n)
    if (c.node_ok[n]) box.add({c.d.nodes[n].x, c.d.nodes[n].y});
  for (const Point& p : c.d.clip) box.add(p);
  if (box.empty()) box.add({0.0, 0.0});
  c.region = box.grown(c.options.probe_margin * c.scale);
}

}  // namespace covmap::check::detail
