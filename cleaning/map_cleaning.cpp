#include "cleaning/tolerances.h"
#include "cleaning/map_cleaning.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include "cleaning/curve_fit.h"
#include "core/parallel.h"
#include "core/readable_numbers.h"
#include "cleaning/arc_graph.h"
#include "cleaning/range_edges.h"
#include "cleaning/ring_labels.h"
#include "cleaning/rings.h"
#include "cleaning/topology.h"

namespace covmap::cleaning {
namespace {


void validate(const CleaningOptions& o) {
  std::string problems;
  if (!std::isfinite(o.snap_distance) || o.snap_distance < 0.0)
    problems += " snap_distance must be finite and >= 0 (0: estimate), got " + std::to_string(o.snap_distance) + ";";
  if (!std::isfinite(o.min_chain_length) || o.min_chain_length < 0.0)
    problems += " min_chain_length must be finite and >= 0, got " + std::to_string(o.min_chain_length) + ";";
  if (!std::isfinite(o.line_preference) || o.line_preference < 1.0)
    problems += " line_preference must be finite and >= 1, got " + std::to_string(o.line_preference) + ";";
  if (o.threads < 1) problems += " threads must be >= 1, got " + std::to_string(o.threads) + ";";
  if (!problems.empty()) {
    problems.pop_back();
    throw std::invalid_argument("clean_coverage_map: invalid options:" + problems);
  }
}

// One placeholder site per sensor for the graph: its id, at the area centroid of its rings
// (recognition estimates the real positions; this one only labels the region).
std::vector<Site> placeholder_sites(const cleaning::MapRings& map) {
  struct Moments {
    double area = 0.0, x = 0.0, y = 0.0;
  };
  std::vector<Moments> m(map.sensors.size());
  for (const auto& ring : map.rings) {
    const Point o = ring.points.front();
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
      const Point a{ring.points[i].x - o.x, ring.points[i].y - o.y};
      const Point b{ring.points[i + 1].x - o.x, ring.points[i + 1].y - o.y};
      const double cross = a.x * b.y - a.y * b.x;
      auto& s = m[static_cast<std::size_t>(ring.sensor)];
      s.area += cross;
      s.x += cross * (o.x + (a.x + b.x) / 3.0);
      s.y += cross * (o.y + (a.y + b.y) / 3.0);
    }
  }
  std::vector<Site> sites;
  for (std::size_t s = 0; s < map.sensors.size(); ++s) {
    Site site;
    site.id = map.sensors[s];
    if (m[s].area != 0.0) site.x = m[s].x / m[s].area, site.y = m[s].y / m[s].area;
    sites.push_back(std::move(site));
  }
  return sites;
}

}  // namespace

SnapTooSmall::SnapTooSmall(double snap_, double perimeter_)
    : std::invalid_argument("the snap distance " + metres(snap_) + " is too small for cell boundaries " +
                            metres(perimeter_) + " long in all (cleaning would take more than " +
                            std::to_string(static_cast<long long>(tolerance::kMaxSamples)) + " samples)"),
      snap(snap_),
      perimeter(perimeter_) {}

CleanedMap clean_coverage_map(std::span<const CoverageCell> cells, const CleaningOptions& options) {
  validate(options);
  cleaning::MapRings rings = cleaning::collect_rings(cells);
  if (rings.rings.empty()) throw std::invalid_argument("clean_coverage_map: the map has no cell with a usable polygon");

  CleanedMap out;
  CleaningReport& report = out.report;
  report.input_vertices = rings.input_vertices;
  report.cells = rings.cells;
  report.sensors = rings.sensors.size();
  report.bin_size_estimate = cleaning::estimate_bin_size(rings.rings);
  double snap = options.snap_distance;
  if (snap == 0.0) {
    snap = report.bin_size_estimate > 0.0 ? cleaning::tolerance::kSnapBins * report.bin_size_estimate
                                          : cleaning::tolerance::kSnapMedianEdges * cleaning::median_edge_length(rings.rings);
  }
  report.snap_distance = snap;
  out.sensors = rings.sensors;
  out.graph.sites = placeholder_sites(rings);

  // Guard against a snap distance far below the map's scale (given, or estimated from a map of
  // a few huge polygons): the work grows with perimeter / snap.
  double perimeter = 0.0;
  for (const auto& ring : rings.rings) perimeter += ring.perimeter();
  if (!(snap > 0.0) || perimeter / (cleaning::tolerance::kSampleSpacing * snap) > cleaning::tolerance::kMaxSamples)
    throw SnapTooSmall(snap, perimeter);
  // The edge index serves only the topology: released before the fits (it is a large part of the
  // memory at its peak).
  cleaning::Topology topology = [&] {
    const cleaning::BoundaryIndex index(rings.rings, snap, options.threads);
    return cleaning::build_topology(index, options.min_chain_length * snap, options.threads);
  }();
  report.junctions_merged = topology.junctions_merged;
  report.short_chains_dropped = topology.short_chains_dropped;
  report.gaps_closed = topology.gaps_closed;
  report.overlaps_resolved = topology.overlaps_resolved;
  report.seams = topology.seams;

  // Fit every boundary chain (interior points only), then settle the junctions on the fits. The
  // fits are independent, so they run on the threads, each into its own slot; the chains are then
  // kept or dropped in order, as before.
  const double huber = cleaning::tolerance::kHuberThreshold * snap;
  std::vector<cleaning::FittedCurve> fits(topology.chains.size());
  parallel_items(topology.chains.size(), options.threads, [&](std::size_t k) {
    const cleaning::RawChain& raw = topology.chains[k];
    if (raw.sensor_b == kNone) return;
    if (raw.from == kNone || raw.from == raw.to) {  // a loop
      fits[k] = cleaning::fit_curve(raw.points, huber, options.line_preference, true);
    } else if (raw.points.size() >= cleaning::tolerance::kMinFitPoints) {
      fits[k] = cleaning::fit_curve(raw.points, huber, options.line_preference, false);
    } else {
      // Too few points of its own (its copies hardly face each other): the junctions help.
      std::vector<Point> with_ends{topology.junctions[static_cast<std::size_t>(raw.from)]};
      with_ends.insert(with_ends.end(), raw.points.begin(), raw.points.end());
      with_ends.push_back(topology.junctions[static_cast<std::size_t>(raw.to)]);
      fits[k] = cleaning::fit_curve(with_ends, huber, options.line_preference, false);
    }
  });
  for (std::size_t k = 0; k < topology.chains.size(); ++k) {
    cleaning::RawChain& raw = topology.chains[k];
    BoundaryChain chain;
    chain.sensor_a = raw.sensor_a;
    chain.sensor_b = raw.sensor_b;
    chain.from = raw.from;
    chain.to = raw.to;
    chain.points = std::move(raw.points);
    if (chain.sensor_b != kNone) {
      chain.fit = std::move(fits[k]);
      const bool loop = chain.from == kNone || chain.from == chain.to;
      if (loop && (chain.points.size() < cleaning::tolerance::kMinFitPoints ||
                   !std::holds_alternative<Circle>(chain.fit.curve))) {
        // A loop whose copies hardly face each other: nothing to draw a circle through.
        ++report.short_chains_dropped;
        continue;
      }
    }
    out.chains.push_back(std::move(chain));
  }
  out.junctions = topology.junctions;
  report.nodes_snapped = cleaning::refine_junctions(out.junctions, out.chains, snap);

  report.frame_chains = cleaning::finish_chains(out, topology.junctions, snap);
  cleaning::find_range_edges(out, rings, snap, huber, options.line_preference);
  report.range_edges = out.range_edges.size();
  report.chains = out.chains.size();
  report.junctions = out.junctions.size();
  cleaning::build_graph(out, snap, huber, options.threads);
  return out;
}

}  // namespace covmap::cleaning
