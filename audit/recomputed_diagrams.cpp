// Recomputed diagrams of audit(): the MWVD of the refined sensors and of the reported ones, clipped
// to the map's frame, and each compared with the map on a raster.
#include <cmath>
#include <cstdlib>
#include <functional>
#include <future>
#include <tuple>
#include <utility>

#include "audit/audit_stages.h"
#include "voronoi/clip.h"
#include "voronoi/engine.h"

namespace covmap::audit::stages {
namespace {

// The map's frame as a simple counter-clockwise polygon, for clipping recomputed diagrams: the
// longest closed walk along frame arcs; the bounding box when there is none.
std::vector<Point> longest_frame_walk(const Diagram& g, const Box& box) {
  std::vector<int> next(g.nodes.size(), kNone);
  std::vector<int> starts;
  for (std::size_t a = 0; a < g.arcs.size(); ++a) {
    const auto& arc = g.arcs[a];
    if (!arc.frame || arc.from == kNone || arc.to == kNone) continue;
    // The inside is on the left of a frame arc; walk so that the inside stays on the left.
    const bool inside_left = arc.left_site != kNone;
    const int from = inside_left ? arc.from : arc.to, to = inside_left ? arc.to : arc.from;
    next[from] = to;
    starts.push_back(from);
  }
  std::vector<Point> best;
  std::vector<char> seen(g.nodes.size(), 0);
  for (int s : starts) {
    if (seen[s]) continue;
    std::vector<Point> ring;
    int v = s;
    while (v != kNone && !seen[v]) {
      seen[v] = 1;
      ring.push_back({g.nodes[v].x, g.nodes[v].y});
      v = next[v];
    }
    if (v == s && ring.size() > best.size()) best = std::move(ring);
  }
  if (best.size() >= 3) return best;
  return {{box.xmin, box.ymin}, {box.xmax, box.ymin}, {box.xmax, box.ymax}, {box.xmin, box.ymax}};
}

// One side of the comparison: the diagram of `sites` and its agreement with the map.
struct Recomputed {
  Diagram diagram;
  DiagramAgreement agreement;
  std::vector<double> iou;
  Messages messages;
};

// The diagram of `sites` clipped to the frame (to the box when that fails), and what went wrong.
Recomputed recomputed_diagram(const std::vector<Site>& sites, const std::vector<Point>& frame, const Box& box,
                              const char* what) {
  Recomputed r;
  try {
    const Diagram d = voronoi::build_diagram(sites);
    try {
      r.diagram = voronoi::clip_diagram(d, frame);
    } catch (const std::exception& e) {
      r.messages.push_back(std::string(what) + ": clipping to the map's frame failed (" + e.what() + "); clipped to its bounding box");
      r.diagram = voronoi::clip_diagram(d, {{box.xmin, box.ymin}, {box.xmax, box.ymin}, {box.xmax, box.ymax}, {box.xmin, box.ymax}});
    }
  } catch (const std::exception& e) {
    r.messages.push_back(std::string(what) + ": no diagram (" + e.what() + ")");
  }
  return r;
}

// Agreement of the diagram of `sites` with the map, and per sensor its intersection over union.
// With a reception limit (reach R for weight 1), bins beyond every sensor's reach are uncovered.
std::pair<DiagramAgreement, std::vector<double>> agreement_of(const MapRaster& raster, const cleaning::CleanedMap& cleaned,
                                                              const std::vector<Site>& sites, int count,
                                                              std::optional<double> reach) {
  const std::size_t n = cleaned.sensors.size();
  const voronoi::BestServerRaster labels = voronoi::best_server_raster(sites, raster.grid, reach);
  LabelAgreement a = compare_labels(raster.raster, labels.labels, count);
  DiagramAgreement d;
  d.mean_iou = a.mean_iou;
  d.hausdorff_m = a.hausdorff;
  for (int v : a.vanished) d.vanished.push_back(v < static_cast<int>(n) ? cleaned.sensors[v] : std::to_string(v));
  for (int v : a.appeared) d.appeared.push_back(v < static_cast<int>(n) ? cleaned.sensors[v] : std::to_string(v));
  return std::make_pair(d, a.iou);
}

// The reported sensors' own sites: map sensors at their reported values (reconstructed ones
// where a sensor was not reported), then sensors reported but absent from the map.
std::vector<Site> reported_sites(const MapCells& cells, const std::vector<Site>& refined_sites,
                                 const ReportedOf& reported_of, std::span<const ReportedSensor> reported,
                                 const WeightScale& scale, const AuditOptions& options) {
  const double log_factor = scale.log_factor;
  std::vector<Site> rs = refined_sites;
  for (auto [i, r] : reported_of) {
    rs[i].x = r->position.x, rs[i].y = r->position.y;
    std::optional<double> wr = r->weight;
    if (!wr && r->tx_power_dbm && options.alpha) wr = std::pow(10.0, *r->tx_power_dbm / (10.0 * *options.alpha));
    rs[i].weight = wr ? *wr / std::exp(log_factor) : refined_sites[i].weight;
  }
  for (const ReportedSensor& r : reported) {
    if (cells.index.count(r.id)) continue;
    std::optional<double> wr = r.weight;
    if (!wr && r.tx_power_dbm && options.alpha) wr = std::pow(10.0, *r.tx_power_dbm / (10.0 * *options.alpha));
    rs.push_back({r.id, r.position.x, r.position.y, wr ? *wr / std::exp(log_factor) : 1.0});
  }
  return rs;
}

// What both sides are drawn in and compared with: the map, its frame and the refinement's reach.
struct Comparison {
  const MapRaster& raster;
  const cleaning::CleanedMap& cleaned;
  const std::vector<Point>& frame;
  const Box& box;
  std::optional<double> reach;
};

// The side of `sites` (the first `count` of them compared by sensor), named `what` in messages.
Recomputed recompute(const Comparison& with, const std::vector<Site>& sites, int count, const char* what) {
  Recomputed r = recomputed_diagram(sites, with.frame, with.box, what);
  std::tie(r.agreement, r.iou) = agreement_of(with.raster, with.cleaned, sites, count, with.reach);
  return r;
}

}  // namespace

Messages recomputed_diagrams(const VerificationInputs& in, AuditResult& out) {
  const cleaning::CleanedMap& cleaned = in.cleaned;
  const MapCells& cells = in.cells;
  const MapRaster& raster = in.raster;
  const fitting::RefineResult& refined = in.refined;
  const std::span<const ReportedSensor> reported = in.reported;
  const AuditOptions& options = in.options;
  const std::size_t n = cleaned.sensors.size();
  const Box& box = cells.box;
  const std::vector<Point> frame = longest_frame_walk(cleaned.graph, box);
  const std::vector<Site>& refined_sites = refined.sites;
  const std::vector<Site> rs =
      reported.empty() ? std::vector<Site>{} : reported_sites(cells, refined_sites, in.reported_of, reported, in.scale, options);
  const Comparison with{.raster = raster, .cleaned = cleaned, .frame = frame, .box = box, .reach = refined.range};
  // The two sides are independent: the reported one on a second thread when there are threads to
  // spare. Each keeps its own messages, added in a fixed order.
  std::future<Recomputed> reported_side;
  if (!reported.empty())
    reported_side = std::async(options.threads > 1 ? std::launch::async : std::launch::deferred, recompute,
                               std::cref(with), std::cref(rs), static_cast<int>(rs.size()), "reported sensors");
  // The raster of the map (made before the refinement): its own bins where it has them, at most ~4·10⁶.
  Recomputed mine = recompute(with, refined_sites, static_cast<int>(n), "refined sensors");
  out.refined_diagram = std::move(mine.diagram);
  out.refined_agreement = mine.agreement;
  Messages messages = std::move(mine.messages);
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(mine.iou[i])) out.sensors[i].iou_refined = mine.iou[i];
  if (reported.empty()) return messages;
  Recomputed theirs = reported_side.get();
  out.reported_diagram = std::move(theirs.diagram);
  append(messages, theirs.messages);
  DiagramAgreement& d = theirs.agreement;
  // Names of appeared reported-only sensors.
  for (auto& name : d.appeared) {
    const int k = std::atoi(name.c_str());
    if (k >= static_cast<int>(n) && k < static_cast<int>(rs.size())) name = rs[k].id;
  }
  out.reported_agreement = d;
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(theirs.iou[i])) out.sensors[i].iou_reported = theirs.iou[i];
  return messages;
}

}  // namespace covmap::audit::stages
