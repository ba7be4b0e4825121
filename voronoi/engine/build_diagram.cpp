#include <algorithm>
#include <chrono>
#include <cmath>

#include "voronoi/engine.h"
#include "voronoi/diagram_edit.h"
#include "voronoi/faces.h"
#include "voronoi/engine/extractors.h"
#include "voronoi/engine/facet_walk.h"

namespace covmap::voronoi {

namespace engine {

// Collinear lifted sites: every power facet is a whole plane, so each triangulation edge carries
// its full bisector and there are no nodes.
void extract_linear(const std::vector<Site>& sites, RegularTriangulation& rt, Diagram& out) {
  for (auto e = rt.finite_edges_begin(); e != rt.finite_edges_end(); ++e) {
    const int si = site_of(e->first->vertex(e->second));
    const int sj = site_of(e->first->vertex(e->third));
    out.arcs.push_back(make_arc(si, sj, kNone, kNone, sites));
  }
}

// Nearly equal weights give Apollonius circles of enormous radius whose centre and radius cannot
// be written in doubles to better than ~4 ulps of their size, while near its nodes the arc is
// almost straight. A bounded arc whose sagitta chord²/(8r) is below that representation error is
// written as the straight Line through its nodes instead: strictly closer to the true bisector.
constexpr double kHugeCircleRatio = 1e6;  // radius / site spacing: |w_i - w_j| ≲ 1e-6 w

void straighten_flat_arcs(Diagram& d) {
  for (Arc& a : d.arcs) {
    const Circle* c = std::get_if<Circle>(&a.curve);
    if (!c || a.from == kNone || a.to == kNone || a.from == a.to) continue;
    const Node& p = d.nodes[a.from];
    const Node& q = d.nodes[a.to];
    const double chord = std::hypot(q.x - p.x, q.y - p.y);
    const double representation =
        4 * 0x1p-52 * std::max({std::fabs(c->cx), std::fabs(c->cy), c->r});
    // Only circles that are huge against their sites' distance (weights equal to ~6 digits or
    // more) qualify: a tiny arc of an ordinary circle is as well written as a circle, and its
    // curve type tells readers (recognition) that the weights differ.
    const Site& si = d.sites[a.left_site];
    const Site& sj = d.sites[a.right_site];
    const double spacing = std::hypot(sj.x - si.x, sj.y - si.y);
    if (chord > 0 && c->r > kHugeCircleRatio * spacing && chord * chord / (8 * c->r) < representation)
      a.curve = Line{p.x, p.y, q.x - p.x, q.y - p.y};
  }
}

}  // namespace engine

Diagram build_diagram(std::span<const Site> input, BuildStats* stats_out) {
  using namespace engine;
  if (auto problems = find_invalid_sites(input); !problems.empty())
    throw InvalidSites(std::move(problems));
  BuildStats stats;
  Diagram out;
  out.sites.assign(input.begin(), input.end());
  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  auto start = Clock::now();
  std::vector<RawWeightedPoint> points;
  points.reserve(input.size());
  for (std::size_t i = 0; i < input.size(); ++i)
    points.emplace_back(RawPoint(input[i].x, input[i].y, input[i].weight), static_cast<double>(i));
  RegularTriangulation rt(points.begin(), points.end());
  stats.triangulation_seconds = seconds_since(start);
  stats.triangulation_dimension = rt.dimension();
  start = Clock::now();
  if (rt.dimension() == 3)
    extract_spatial(out.sites, rt, out, stats);
  else if (rt.dimension() == 2)
    extract_planar(out.sites, rt, out, stats);
  else
    extract_linear(out.sites, rt, out);
  drop_unused_nodes(out);  // copies left by nodes found twice on a shared power line
  straighten_flat_arcs(out);
  stats.extraction_seconds = seconds_since(start);
  start = Clock::now();
  trace_faces(out);
  stats.faces_seconds = seconds_since(start);
  if (stats_out) *stats_out = stats;
  return out;
}

}  // namespace covmap::voronoi
