#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "core/large_buffer.h"
#include "core/parallel.h"
#include "voronoi/engine.h"
#include "voronoi/diagram_edit.h"
#include "voronoi/faces.h"
#include "voronoi/tolerances.h"
#include "voronoi/engine/build_in_order.h"
#include "voronoi/engine/extractors.h"
#include "voronoi/engine/facet_walk.h"
#include "voronoi/engine/self_check.h"
#include "voronoi/engine/writable_bisectors.h"

namespace covmap::voronoi {

namespace engine {

// Collinear lifted sites: every power facet is a whole plane, so each triangulation edge carries
// its full bisector and there are no nodes.
void extract_linear(const std::vector<Site>& sites, SpatialTriangulation& rt, Diagram& out) {
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
// A line is judged by its own (small) numbers, though, so the sagitta must also be within what
// any arc end may be off its curve (self_check.h's allowed_off): else the circle stays.

void straighten_arc(Arc& a, const Diagram& d, double extent) {
  const Circle* c = std::get_if<Circle>(&a.curve);
  if (!c || a.from == kNone || a.to == kNone || a.from == a.to) return;
  // Only circles that are huge against their sites' distance (weights equal to ~6 digits or
  // more) qualify: a tiny arc of an ordinary circle is as well written as a circle, and its
  // curve type tells readers (recognition) that the weights differ. Tested first: it rules out
  // almost every arc.
  const Site& si = d.sites[a.left_site];
  const Site& sj = d.sites[a.right_site];
  // Most circles are decided without hypot: r² below a quarter of (ratio × spacing)² (rounding
  // errs by a few ulps, the margin is a factor of 4) is certainly not above ratio × hypot.
  // Sites and radii are scaled (build_diagram), so the squares neither overflow nor underflow.
  const double dx = sj.x - si.x, dy = sj.y - si.y;
  constexpr double kQuarterRatio2 = 0.25 * tolerance::kHugeCircleRatio * tolerance::kHugeCircleRatio;
  if (c->r * c->r < kQuarterRatio2 * (dx * dx + dy * dy)) return;
  const double spacing = std::hypot(dx, dy);
  if (!(c->r > tolerance::kHugeCircleRatio * spacing)) return;
  const Node& p = d.nodes[a.from];
  const Node& q = d.nodes[a.to];
  const double chord = std::hypot(q.x - p.x, q.y - p.y);
  const double representation =
      4 * 0x1p-52 * std::max({std::fabs(c->cx), std::fabs(c->cy), c->r});
  const double sagitta = chord * chord / (8 * c->r);
  const double line_allowance = allowed_off(extent, std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(q.x), std::fabs(q.y)}));
  if (chord > 0 && sagitta < representation && sagitta <= line_allowance)
    a.curve = Line{p.x, p.y, q.x - p.x, q.y - p.y};
}

// Each arc on its own: on all cores.
void straighten_flat_arcs(Diagram& d) {
  const double extent = site_extent(d.sites);
  parallel_chunks(d.arcs.size(), worker_count(d.arcs.size()), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) straighten_arc(d.arcs[k], d, extent);
  });
}

// The engine works on sites scaled by powers of two: positions so that the largest |coordinate| is
// in [0.5, 1), weights so that the largest is in [0.5, 1). Scaling by a power of two changes no
// bit of a double's mantissa, and the diagram of scaled sites is the scaled diagram (positions
// scale it, weights only enter as ratios), so every exact decision is the one the input asked
// for. What the scaling buys is range: the lifted coordinates and the double constructions stay
// far from overflow (unscaled, sites at 1e15 give infinite nodes) and from the magnitudes at
// which the engine's internal thresholds were chosen (unscaled, sites at 1e9 give a wrong
// diagram). A site whose
// scaled value would leave the normal range of doubles (coordinates or weights spanning more
// than ~600 orders of magnitude) is refused: it cannot be scaled exactly.
struct Scaling {
  int position_exponent = 0;  // stored = input * 2^-position_exponent
  int weight_exponent = 0;
};

Scaling scaling_for(std::span<const Site> sites) {
  double position = 0.0, weight = 0.0;
  for (const Site& s : sites) {
    position = std::max({position, std::fabs(s.x), std::fabs(s.y)});
    weight = std::max(weight, s.weight);
  }
  Scaling scaling;
  if (position > 0) std::frexp(position, &scaling.position_exponent);
  std::frexp(weight, &scaling.weight_exponent);
  return scaling;
}

// Why site s (scaled to x, y, w) cannot be scaled exactly: which of its values underflows, and
// beside which largest value. Typically a coordinate moved off 0 by an ulp (4.9e-324, a denormal),
// or values spanning more than ~600 orders of magnitude.
std::string unscalable(const Site& s, double x, double y, double w, const Scaling& scaling) {
  const auto lost = [](double v, double scaled, int e) { return std::ldexp(scaled, e) != v || (v != 0 && !std::isnormal(scaled)); };
  std::ostringstream m;
  m.precision(3);
  if (lost(s.weight, w, scaling.weight_exponent))
    m << "its weight " << s.weight << " is too small beside the largest weight (about 2^" << scaling.weight_exponent;
  else
    m << "its coordinate " << (lost(s.x, x, scaling.position_exponent) ? s.x : s.y)
      << " is too small beside the largest coordinate (about 2^" << scaling.position_exponent;
  m << ") to be represented exactly with it (a denormal number, or values spanning more than ~600 orders of "
       "magnitude); write 0 if 0 is meant";
  return m.str();
}

// v · 2^e: a product by a power of two, the same double as std::ldexp(v, e) (both are rounded
// once, and not at all when the result is normal), at a fraction of its cost; ldexp itself when
// 2^e is not a normal double.
struct PowerOfTwo {
  int exponent = 0;
  double factor = 1.0;  // 2^exponent, or 0 when that is not a normal double
  explicit PowerOfTwo(int e) : exponent(e), factor(e >= -1022 && e <= 1023 ? std::ldexp(1.0, e) : 0.0) {}
  double operator()(double v) const { return factor != 0.0 ? v * factor : std::ldexp(v, exponent); }
};

// Site s scaled: (x, y, w) and whether all three are exact — a scaled value is exact when it is
// normal or zero (a normal product by a power of two is not rounded, and scaling back is then
// exact too, since the largest value scales to below 1).
struct ScaledSite {
  double x, y, w;
  bool exact;
};
ScaledSite scale_site(const Site& s, const PowerOfTwo& position, const PowerOfTwo& weight) {
  const auto exact = [](double v, double scaled) { return v == 0 || std::isnormal(scaled); };
  ScaledSite r{position(s.x), position(s.y), weight(s.weight), false};
  r.exact = exact(s.x, r.x) && exact(s.y, r.y) && exact(s.weight, r.w);
  return r;
}

std::vector<Site> scaled_sites(std::span<const Site> input, const Scaling& scaling) {
  std::vector<Site> sites(input.begin(), input.end());
  std::vector<InvalidSite> problems;
  const PowerOfTwo position(-scaling.position_exponent), weight(-scaling.weight_exponent);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    Site& s = sites[i];
    const ScaledSite scaled = scale_site(s, position, weight);
    if (!scaled.exact) problems.push_back({static_cast<int>(i), s.id, unscalable(s, scaled.x, scaled.y, scaled.w, scaling)});
    s.x = scaled.x;
    s.y = scaled.y;
    s.weight = scaled.w;
  }
  if (!problems.empty()) throw InvalidSites(std::move(problems));
  return sites;
}

// The lifted sites for the triangulation, each (x, y, w) scaled as scaled_sites does and its
// index in the weight slot; empty if some value cannot be scaled exactly (scaled_sites then says
// which). It copies no site (their names and ids), so that the copy can be made beside the
// insertion (BesideTriangulation).
std::vector<RawWeightedPoint> scaled_points(std::span<const Site> input, const Scaling& scaling) {
  std::vector<RawWeightedPoint> points;
  points.reserve(input.size());
  advise_huge_pages(points.data(), points.capacity() * sizeof(RawWeightedPoint));
  const PowerOfTwo position(-scaling.position_exponent), weight(-scaling.weight_exponent);
  for (std::size_t i = 0; i < input.size(); ++i) {
    const ScaledSite s = scale_site(input[i], position, weight);
    if (!s.exact) return {};
    points.emplace_back(RawPoint(s.x, s.y, s.w), static_cast<double>(i));
  }
  return points;
}

// Scales the geometry back to the input's units; refuses a diagram whose nodes or curves do not fit
// in doubles at the input's scale (a node beyond ±1.8e308), naming the sites of the first one.
void scale_back(Diagram& d, const Scaling& scaling) {
  const PowerOfTwo scale(scaling.position_exponent);
  const auto up = [&scale](double& v) { v = scale(v); };
  // Every value on its own: on all cores.
  parallel_chunks(d.nodes.size(), worker_count(d.nodes.size()), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      up(d.nodes[k].x);
      up(d.nodes[k].y);
    }
  });
  parallel_chunks(d.arcs.size(), worker_count(d.arcs.size()), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      Arc& a = d.arcs[k];
      if (Circle* c = std::get_if<Circle>(&a.curve)) {
        up(c->cx);
        up(c->cy);
        up(c->r);
      } else if (Line* l = std::get_if<Line>(&a.curve)) {
        up(l->x);
        up(l->y);
        up(l->dx);
        up(l->dy);
      }
    }
  });
  for (const Arc& a : d.arcs) {
    const Circle* c = std::get_if<Circle>(&a.curve);
    const Line* l = std::get_if<Line>(&a.curve);
    const bool finite = c ? std::isfinite(c->cx) && std::isfinite(c->cy) && std::isfinite(c->r)
                          : std::isfinite(l->x) && std::isfinite(l->y) && std::isfinite(l->dx) && std::isfinite(l->dy);
    const bool ends = (a.from == kNone || (std::isfinite(d.nodes[a.from].x) && std::isfinite(d.nodes[a.from].y))) &&
                      (a.to == kNone || (std::isfinite(d.nodes[a.to].x) && std::isfinite(d.nodes[a.to].y)));
    if (finite && ends) continue;
    std::vector<InvalidSite> problems;
    for (int site : {a.left_site, a.right_site})
      if (site != kNone)
        problems.push_back({site, d.sites[site].id,
                            "the bisector it shares with another site runs beyond ±1.8e308, the largest double; "
                            "scale the coordinates down"});
    throw InvalidSites(std::move(problems));
  }
}

// Whether every site has finite coordinates and a finite positive weight: then the lifted
// predicates and CGAL's triangulation are well defined, whatever else find_invalid_sites may find
// (duplicates, near duplicates, values outside the supported range).
bool finite_with_positive_weights(std::span<const Site> sites) {
  for (const Site& s : sites)
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.weight) || !(s.weight > 0.0)) return false;
  return true;
}

// The validation of large inputs, run on a second thread beside the scaling and the triangulation
// (a small fraction of the insertion's time, which keeps only one core busy), with the
// triangulation's vertex arrays (flat_vertices) after it, and before it the memory the insertion
// will take its blocks from faulted in (engine/cell_arena.h). Its verdict is taken before anything
// else is reported, so a build throws the same InvalidSites as when it validated first.
class BesideTriangulation {
 public:
  explicit BesideTriangulation(std::span<const Site> input) : input_(input) {}
  ~BesideTriangulation() { join(); }

  // Starts the validation, and when `spatial` the prefault before it and flat_vertices(sites) after.
  // With `scale`, `sites` is first filled with the scaled copy of the input (scaled_sites), which
  // the caller reads only after check(): a copy of every site's id and name (most of its cost the
  // first touch of its pages), that the insertion need not wait for.
  void start(std::vector<Site>& sites, const Scaling* scale, bool spatial) {
    thread_ = std::thread([this, &sites, scale, spatial] {
      try {
        // CGAL's container ends with ~6.2 cells a site for uniform weights (~5 for the most
        // correlated weights): 6 are faulted in, what is missing is mapped on demand and what is
        // left over unmapped after the insertion.
        if (spatial)
          arena_prefault(input_.size() * (kPrefaultCellsPerSite * sizeof(SpatialCell) + sizeof(SpatialVertex)));
        if (scale) sites = scaled_sites(input_, *scale);
        problems_ = find_invalid_sites(input_);
        if (spatial && problems_.empty()) vertices_ = flat_vertices(sites);
      } catch (...) {
        failure_ = std::current_exception();
      }
    });
    started_ = true;
  }

  // Waits for the thread (or validates now if it was never started) and throws InvalidSites if the
  // sites are invalid, or what the thread threw.
  void check() {
    join();
    if (!started_) {
      problems_ = find_invalid_sites(input_);
      started_ = true;
    }
    if (failure_) std::rethrow_exception(failure_);
    if (!problems_.empty()) throw InvalidSites(std::move(problems_));
  }

  std::optional<FlatVertices>& vertices() { return vertices_; }

 private:
  static constexpr std::size_t kPrefaultCellsPerSite = 6;

  // Joins the thread; what it prefaulted and the insertion did not take is unmapped.
  void join() {
    if (!thread_.joinable()) return;
    thread_.join();
    arena_release_prefaulted();
  }

  std::span<const Site> input_;
  std::thread thread_;
  bool started_ = false;
  std::vector<InvalidSite> problems_;
  std::optional<FlatVertices> vertices_;
  std::exception_ptr failure_;
};

}  // namespace engine

Diagram engine::build_diagram_in_order(std::span<const Site> input, InsertionOrder order, BuildStats* stats_out) {
  using namespace engine;
  // Small inputs, and any with a value the arithmetic cannot take, are validated first; large ones
  // beside the triangulation (BesideTriangulation).
  const bool beside = worker_count(input.size()) > 1 && finite_with_positive_weights(input);
  if (!beside)
    if (auto problems = find_invalid_sites(input); !problems.empty()) throw InvalidSites(std::move(problems));
  BesideTriangulation helper(input);
  BuildStats stats;
  Diagram out;
  const Scaling scaling = scaling_for(input);
  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  auto start = Clock::now();
  std::vector<RawWeightedPoint> points = scaled_points(input, scaling);
  // The diagram's scaled copy of the sites is made beside the insertion when the helper runs and
  // every value scales exactly; else here, where it throws if some value cannot be scaled.
  const bool sites_beside = beside && !points.empty();
  if (!sites_beside) {
    try {
      out.sites = scaled_sites(input, scaling);
    } catch (...) {
      if (beside) helper.check();
      throw;
    }
  }
  // One cell layout in every dimension (regular_triangulation.h). A spatial triangulation is
  // copied into flat arrays (timed with the extraction) and released before extracting.
  std::optional<FlatTriangulation> flat;
  {
    const bool spatial = lifted::span_space(points);  // exact: CGAL's dimension must agree
    // The triangulation's blocks come from fresh huge pages (engine/cell_arena.h), not from
    // memory freed earlier in the process, so that memory is returned first: else it stays
    // resident beside them and raises the peak memory of repeated builds.
    trim_heap();
    if (beside) helper.start(out.sites, sites_beside ? &scaling : nullptr, spatial);
    std::optional<SpatialTriangulation> rt_storage;
    try {
      rt_storage.emplace();
      // The spatial extractor's output does not depend on the insertion order; the planar one's
      // follows CGAL's container order, so coplanar lifted sites keep the (x, y, w) order.
      insert_spatially_sorted(*rt_storage, points, spatial ? order : InsertionOrder::kSpatial3);
    } catch (...) {
      if (beside) helper.check();
      throw;
    }
    SpatialTriangulation& rt = *rt_storage;
    if (beside) helper.check();
    if ((rt.dimension() == 3) != spatial)
      throw EngineFailure("the triangulation's dimension disagrees with the exact rank of the lifted sites");
    std::vector<RawWeightedPoint>().swap(points);  // the vertices hold copies
    stats.triangulation_seconds = seconds_since(start);
    stats.triangulation_dimension = rt.dimension();
    start = Clock::now();
    if (rt.dimension() == 3)
      flat = flatten_triangulation(out.sites, helper.vertices() ? std::move(*helper.vertices()) : flat_vertices(out.sites), rt);
    else if (rt.dimension() == 2)
      extract_planar(out.sites, rt, out, stats);
    else
      extract_linear(out.sites, rt, out);
  }
  if (flat) extract_spatial(out.sites, std::move(*flat), out, stats);
  // The extractor's arrays (the build's largest) are released by now; core/large_buffer.h would
  // keep up to 1 GiB of them resident for reuse, but face tracing needs other sizes, and the cache
  // would hold the build's peak memory through its last stage.
  release_large_buffers();
  drop_unused_nodes(out);  // copies left by nodes found twice on a shared power line
  refuse_unwritable_bisectors(out);
  const auto check_start = Clock::now();
  self_check(out);  // before straightening: it reads each circle's arcs in walk order
  stats.self_check_seconds = seconds_since(check_start);
  straighten_flat_arcs(out);
  stats.extraction_seconds = seconds_since(start);
  start = Clock::now();
  trace_faces(out);
  stats.faces_seconds = seconds_since(start);
  scale_back(out, scaling);
  out.sites.assign(input.begin(), input.end());
  if (stats_out) *stats_out = stats;
  return out;
}

// Spatial inputs are inserted in the (x, y) Hilbert order: the output is the same in every order
// (engine/flat_triangulation.h), and this one inserts faster (regular_triangulation.h).
Diagram build_diagram(std::span<const Site> input, BuildStats* stats_out) {
  return engine::build_diagram_in_order(input, engine::InsertionOrder::kHilbert2, stats_out);
}

}  // namespace covmap::voronoi
