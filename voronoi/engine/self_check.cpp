#include "voronoi/engine/self_check.h"

#include <algorithm>
#include <exception>
#include <cmath>
#include <sstream>
#include <string>

#include "core/parallel.h"
#include "voronoi/engine.h"
#include "voronoi/tolerances.h"

namespace covmap::voronoi::engine {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

[[noreturn]] void fail(const Diagram& d, const Arc& a, const std::string& what) {
  std::ostringstream m;
  m << "the engine's self-check rejected its own diagram: " << what << " (the bisector of sites "
    << a.left_site << " ('" << d.sites[a.left_site].id << "') and " << a.right_site << " ('"
    << d.sites[a.right_site].id << "'))";
  throw EngineFailure(m.str());
}

// Counter-clockwise turn from angle a to angle b, in [0, 2π); equal angles turn 0.
double turn(double a, double b) {
  double t = std::fmod(b - a, kTwoPi);
  return t < 0 ? t + kTwoPi : t;
}

}  // namespace

double site_extent(const std::vector<Site>& sites) {
  double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
  for (const Site& s : sites) {
    xmin = std::min(xmin, s.x), xmax = std::max(xmax, s.x);
    ymin = std::min(ymin, s.y), ymax = std::max(ymax, s.y);
  }
  return std::hypot(xmax - xmin, ymax - ymin);
}

double allowed_off(double extent, double magnitude) {
  return tolerance::kSelfCheckOnCurve * extent + tolerance::kSelfCheckUlps * 0x1p-52 * magnitude;
}

namespace {

void check_ends(const Diagram& d, const Arc& a, double extent) {
  for (int n : {a.from, a.to}) {
    if (n == kNone) continue;
    const Node& p = d.nodes[n];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(d, a, "an end node is not finite");
    double off, magnitude = std::max(std::fabs(p.x), std::fabs(p.y));
    if (const Circle* c = std::get_if<Circle>(&a.curve)) {
      off = std::fabs(std::hypot(p.x - c->cx, p.y - c->cy) - c->r);
      magnitude = std::max({magnitude, std::fabs(c->cx), std::fabs(c->cy), c->r});
    } else {
      const Line& l = std::get<Line>(a.curve);
      off = std::fabs((p.x - l.x) * l.dy - (p.y - l.y) * l.dx) / std::hypot(l.dx, l.dy);
      magnitude = std::max({magnitude, std::fabs(l.x), std::fabs(l.y)});
    }
    const double allowed = allowed_off(extent, magnitude);
    if (!(off <= allowed)) {
      std::ostringstream m;
      m << "node " << n << " is " << off << " off the arc's curve (allowed " << allowed << ")";
      fail(d, a, m.str());
    }
  }
}

}  // namespace

std::size_t pair_run_end(const Diagram& d, std::size_t begin) {
  const Arc& a = d.arcs[begin];
  std::size_t end = begin + 1;
  while (end < d.arcs.size() && d.arcs[end].left_site == a.left_site && d.arcs[end].right_site == a.right_site) ++end;
  return end;
}

int circle_winding(const Diagram& d, std::size_t begin, std::size_t end) {
  const Arc& first = d.arcs[begin];
  const Circle& c = std::get<Circle>(first.curve);
  const Site& si = d.sites[first.left_site];
  const Site& sj = d.sites[first.right_site];
  if (c.r > tolerance::kHugeCircleRatio * std::hypot(sj.x - si.x, sj.y - si.y)) return -1;
  const double sense = first.ccw ? 1.0 : -1.0;
  auto angle = [&](int n) { return sense * std::atan2(d.nodes[n].y - c.cy, d.nodes[n].x - c.cx); };
  double total = 0;
  for (std::size_t k = begin; k < end; ++k) {
    const Arc& a = d.arcs[k];
    if (a.from == kNone || a.from == a.to) return -1;
    const Arc& next = d.arcs[k + 1 < end ? k + 1 : begin];
    total += turn(angle(a.from), angle(a.to)) + turn(angle(a.to), angle(next.from));
  }
  return static_cast<int>(std::round(total / kTwoPi));
}

namespace {

// Calls check(k) for every k in [0, n) on all cores and, if any call throws, rethrows what the
// lowest such k threw: the failure a sequential loop would report.
template <class Check>
void check_all(std::size_t n, Check&& check) {
  const int workers = worker_count(n);
  std::vector<std::exception_ptr> failure(workers);
  parallel_chunks(n, workers, [&](std::size_t begin, std::size_t end, int w) {
    try {
      for (std::size_t k = begin; k < end; ++k) check(k);
    } catch (...) {
      failure[w] = std::current_exception();
    }
  });
  for (const std::exception_ptr& f : failure)
    if (f) std::rethrow_exception(f);
}

}  // namespace

void self_check(const Diagram& d) {
  const double extent = site_extent(d.sites);
  check_all(d.arcs.size(), [&](std::size_t k) {
    const Arc& a = d.arcs[k];
    check_ends(d, a, extent);
    const Line* l = std::get_if<Line>(&a.curve);
    if (l && a.from != kNone && a.to != kNone && a.from != a.to) {
      const Node& p = d.nodes[a.from];
      const Node& q = d.nodes[a.to];
      // Nodes split by rounding (a degree-4 node of nearly cocircular sites) may come out a few
      // ulps out of order; a line arc's extent is read along its direction, so that is harmless.
      const double along = ((q.x - p.x) * l->dx + (q.y - p.y) * l->dy) / std::hypot(l->dx, l->dy);
      const double magnitude = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(q.x), std::fabs(q.y)});
      if (along < -allowed_off(extent, magnitude)) fail(d, a, "a line arc runs against its direction");
    }
  });
  // Every valid site owns a neighbourhood of itself (coincident sites are refused), so with two or
  // more sites each one bounds some arc; a site without any has lost its whole region.
  if (d.sites.size() > 1) {
    std::vector<bool> bounds(d.sites.size(), false);
    for (const Arc& a : d.arcs)
      for (int s : {a.left_site, a.right_site})
        if (s >= 0) bounds[s] = true;
    for (std::size_t s = 0; s < d.sites.size(); ++s)
      if (!bounds[s])
        throw EngineFailure("the engine's self-check rejected its own diagram: site " + std::to_string(s) + " ('" +
                            d.sites[s].id + "') bounds no arc, so its region was lost");
  }
  // The arcs of each circle, in walk order, and the gaps between them must turn around it once.
  // Each run of arcs of one pair of sites is checked from its first arc.
  check_all(d.arcs.size(), [&](std::size_t begin) {
    const Arc& a = d.arcs[begin];
    if (begin > 0 && d.arcs[begin - 1].left_site == a.left_site && d.arcs[begin - 1].right_site == a.right_site) return;
    if (!std::holds_alternative<Circle>(a.curve)) return;
    const int winding = circle_winding(d, begin, pair_run_end(d, begin));
    if (winding == 0) fail(d, a, "an arc's distinct end nodes round to one point, so its sweep cannot be read");
    if (winding > 1) fail(d, a, "the rounded nodes of its arcs are out of the order the exact walk found");
  });
}

}  // namespace covmap::voronoi::engine
